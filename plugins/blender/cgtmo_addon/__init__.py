"""cgtmo for Blender: tone-maps renders with the cgtmo C++ library (through its Python module)
and prepares scenes for the scene-aware CG-TMO operator (passes, light groups, probe, sidecar).

Operators, panels, properties and render handlers live in their own modules; this file only
registers them. Install from the zip that scripts/build_blender_addon.sh builds
(docs/plugins.md)."""

bl_info = {
    "name": "cgtmo tone mapping",
    "author": "cgtmo",
    "version": (0, 1, 0),  # the zip gets the CMake project version (plugins/blender/make_zip.py)
    "blender": (3, 4, 0),
    "location": "Properties > Render > cgtmo Tone Mapping",
    "description": "Tone-map renders with the cgtmo operators (every global operator and CG-TMO), "
                   "prepare passes, light groups, adaptation probe and sidecar",
    "doc_url": "",
    "category": "Render",
}

from . import engine, handlers, operators, panels, properties  # noqa: E402

_modules = (properties, operators, panels, handlers)


def register():
    for m in _modules:
        m.register()


def unregister():
    for m in reversed(_modules):
        m.unregister()
