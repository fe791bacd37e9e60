"""Access to the cgtmo library module and to the scene generator's shared code.

The module (`cgtmo`, pybind11 over the C++ library) is bundled in the add-on zip next to this
file; a module on PYTHONPATH is the fallback (running from a build tree). The scene generator's
modules (scripts/blender/: scene_kit.py, render_scene.py) are bundled under generator/ so that the
add-on writes the same sidecar, probe and emitter records as the test scenes."""
import importlib
import os
import sys

_lib = None
_lib_error = None


class CgtmoError(Exception):
    """A problem to show the user as one line (no traceback)."""


def lib():
    """The cgtmo module; raises CgtmoError with the reason when it cannot be imported."""
    global _lib, _lib_error
    if _lib is not None:
        return _lib
    if _lib_error is None:
        try:
            _lib = importlib.import_module(__package__ + ".cgtmo")
        except ImportError as bundled:
            try:
                _lib = importlib.import_module("cgtmo")
            except ImportError as e:
                _lib_error = "the cgtmo Python module cannot be imported (%s; bundled: %s)" % (e, bundled)
    if _lib is None:
        raise CgtmoError(_lib_error)
    return _lib


def generator():
    """(scene_kit, render_scene) from the bundled copy of scripts/blender, or from the source tree."""
    here = os.path.dirname(os.path.abspath(__file__))
    for folder in (os.path.join(here, "generator"),
                   os.path.join(here, "..", "..", "..", "scripts", "blender")):
        if os.path.exists(os.path.join(folder, "render_scene.py")):
            folder = os.path.abspath(folder)
            if folder not in sys.path:
                sys.path.insert(0, folder)
            import render_scene  # noqa: E402  (imports scene_kit from the same folder)
            import scene_kit  # noqa: E402
            return scene_kit, render_scene
    raise CgtmoError("the scene generator's modules (scripts/blender) are missing from the add-on")


_catalogue = []


def catalogue():
    """Every operator the add-on offers: the library's registry as `cgtmo list --json` lists it
    (name, scope 'pixel' or 'scene', kind, summary, citation, params), in its order."""
    if not _catalogue:
        _catalogue.extend(dict(op) for op in lib().operators())
    return _catalogue


def is_scene_operator(name):
    """Whether the operator reads the scene (passes, light groups, probe, sidecar): scope 'scene'."""
    try:
        return any(op["name"] == name and op["scope"] == "scene" for op in catalogue())
    except CgtmoError:
        return False


def passes_needed(name, params=None):
    """The view-layer flags (use_pass_*) an operator needs besides Combined; () for global ones.
    The library says whether the operator, with these parameters, reads the G-buffer."""
    if not is_scene_operator(name):
        return ()
    m = lib()
    gbuffer = m.scene_needs(name, params or {})["gbuffer"]
    flags = ["use_pass_z"]  # Depth: the background mask (1e10 where no geometry)
    if gbuffer:
        flags += ["use_pass_normal", "use_pass_position", "use_pass_diffuse_color"]
    return tuple(flags)


def identifier(name):
    """A Python identifier for a registry name (operator names contain dashes)."""
    out = "".join(c if c.isalnum() else "_" for c in name)
    return out if not out[:1].isdigit() else "_" + out
