"""Scene settings (scene.cgtmo). The operator list and one property group per operator are
generated from the library's registry at register time, so a new operator needs no edit here."""
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, PointerProperty, StringProperty

from . import engine

_classes = []          # generated classes, in registration order
_param_specs = {}      # operator name -> list of parameter dicts (from the registry)
_enum_cache = {}       # keeps dynamic EnumProperty items alive (Blender requirement)
_settings_class = None


def param_specs(op_name):
    return _param_specs.get(op_name, [])


def param_group(settings, op_name):
    return getattr(settings, "op_" + engine.identifier(op_name), None)


def _float32_text(x):
    # Blender stores FloatProperty as float32: pass the shortest text that reads back the same
    # float32, so the library sees 0.85 and not 0.8500000238.
    import numpy as np
    return str(np.float32(x))


def chosen_params(settings):
    """The parameters the user changed from the registry defaults, as the library's key=value map
    (an 'auto' parameter, whose default is an image statistic, is left out)."""
    group = param_group(settings, settings.operator)
    out = {}
    if group is None:
        return out
    for p in param_specs(settings.operator):
        name = p["name"]
        if p.get("default_from") and getattr(group, name + "_auto"):
            continue
        value = getattr(group, name)
        if p["type"] == "number":
            if _float32_text(value) != _float32_text(p["default"]):
                out[name] = _float32_text(value)
        elif value != p["default"]:
            out[name] = value
    return out


def _param_property(p):
    label = p["name"]
    if p["type"] == "number":
        lo, hi = float(p["min"]), float(p["max"])
        return FloatProperty(name=label, description=p["help"], default=float(p["default"]), min=lo, max=hi,
                             soft_min=lo, soft_max=min(hi, max(lo + 1.0, 10.0 * abs(p["default"]) + 1.0)),
                             precision=4, step=1)
    if p["type"] == "choice":
        items = [(c, c, "") for c in p["choices"]]
        return EnumProperty(name=label, description=p["help"], items=items, default=p["default"])
    return StringProperty(name=label, description=p["help"], default=p["default"])


def _make_operator_group(op):
    ann = {}
    for p in op["params"]:
        ann[p["name"]] = _param_property(p)
        if p.get("default_from"):
            ann[p["name"] + "_auto"] = BoolProperty(
                name="Auto", default=True,
                description="Take %s from the image (%s)" % (p["name"], p["default_from"].replace("_", " ")))
    cls = type("CGTMO_PG_op_" + engine.identifier(op["name"]), (bpy.types.PropertyGroup,), {"__annotations__": ann})
    return cls


_config_cache = {}


def _color_config(settings):
    """The config's displays and views, read once per (path, $OCIO): the panel asks on every redraw."""
    import os
    key = (bpy.path.abspath(settings.color_config), os.environ.get("OCIO", ""))
    if key not in _config_cache:
        try:
            _config_cache[key] = engine.lib().color_config(key[0])
        except Exception:  # noqa: BLE001 - a bad path shows as an empty list; apply() reports it
            return {"displays": {}, "default_display": "", "looks": [], "colorspaces": [], "origin": "unavailable"}
    return _config_cache[key]


def _display_items(self, context):
    cfg = _color_config(self)
    items = [("DEFAULT", "Default (%s)" % cfg["default_display"], "The config's default display")]
    items += [(d, d, "") for d in cfg["displays"]]
    _enum_cache["display"] = items
    return items


def _view_items(self, context):
    cfg = _color_config(self)
    display = cfg["default_display"] if self.display == "DEFAULT" else self.display
    views = cfg["displays"].get(display, [])
    items = [("DEFAULT", "Default (%s)" % ("Standard" if "Standard" in views else (views[0] if views else "")),
              "Standard when the display has it, else the display's default view")]
    items += [(v, v, "") for v in views]
    _enum_cache["view"] = items
    return items


def _colorspace_items(self, context):
    cfg = _color_config(self)
    items = [("AUTO", "Automatic", "The file's chromaticities attribute, else the config's scene_linear role "
                                   "(Blender writes its renders in its scene_linear space)")]
    items += [(c, c, "") for c in cfg.get("colorspaces", [])]
    _enum_cache["input_colorspace"] = items
    return items


def chosen_colorspace(settings):
    """The colorspace= argument of the library's apply functions ("" = automatic)."""
    return "" if settings.input_colorspace == "AUTO" else settings.input_colorspace


def _make_settings_class(ops, max_exposure):
    ann = {
        "enabled": BoolProperty(name="Tone-map renders", default=True,
                                description="After every rendered frame (F12, -f, -a), tone-map it with the chosen "
                                            "operator and write the result next to the render"),
        "operator": EnumProperty(name="Operator", items=[(o["name"], o["name"], o["summary"]) for o in ops],
                                 default="drago" if any(o["name"] == "drago" for o in ops) else ops[0]["name"],
                                 description="cgtmo operator (the registry's global operators and CG-TMO)"),
        "exposure": FloatProperty(name="Exposure", default=0.0, min=-max_exposure, max=max_exposure, soft_min=-10.0,
                                  soft_max=10.0,
                                  description="Stops, applied before the operator", precision=2, step=10),
        "color_config": StringProperty(name="OCIO config", subtype="FILE_PATH", default="",
                                       description="OpenColorIO config for the written image (empty: $OCIO, else "
                                                   "cgtmo's built-in sRGB/Rec.1886/P3 config)"),
        "input_colorspace": EnumProperty(name="Input colour space", items=_colorspace_items,
                                         description="Colour space of the render, converted to linear Rec.709 "
                                                     "before tone mapping (a space of the OCIO config above)"),
        "display": EnumProperty(name="Display", items=_display_items),
        "view": EnumProperty(name="View", items=_view_items),
        "output_format": EnumProperty(name="Format", default="png", items=[
            ("png", "PNG", "8-bit PNG"), ("tif", "TIFF", "16-bit TIFF"), ("jpg", "JPEG", "8-bit JPEG"),
            ("exr", "OpenEXR", "float EXR (display-encoded values)")]),
        "prepare_frames": EnumProperty(name="Probe frames", default="CURRENT", items=[
            ("CURRENT", "Current frame", "Probe and sidecar for the current frame"),
            ("RANGE", "Frame range", "Probe and sidecar for every frame of the scene's range (animations)")]),
        "probe_samples": bpy.props.IntProperty(name="Probe samples", default=64, min=1, max=65536,
                                               description="Samples per pixel of the 64x32 probe render"),
        "last_message": StringProperty(name="Last message", default=""),
        "last_level": StringProperty(name="Last level", default=""),
        "last_output": StringProperty(name="Last output", default="", subtype="FILE_PATH"),
    }
    for op in ops:
        group = _make_operator_group(op)
        _classes.append(group)
        ann["op_" + engine.identifier(op["name"])] = PointerProperty(type=group)
    return type("CGTMO_PG_settings", (bpy.types.PropertyGroup,), {"__annotations__": ann})


def register():
    global _settings_class
    try:
        ops = engine.catalogue()
        max_exposure = float(engine.lib().max_exposure_stops)  # the range the library accepts
    except engine.CgtmoError as e:
        print("cgtmo: error: %s" % e)
        ops = []  # without the library the add-on has no operator to offer
        max_exposure = 0.0  # nor any exposure to apply
    _param_specs.clear()
    _param_specs.update({o["name"]: o["params"] for o in ops})
    _classes.clear()
    _settings_class = _make_settings_class(ops, max_exposure)
    _classes.append(_settings_class)
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.cgtmo = PointerProperty(type=_settings_class)


def unregister():
    del bpy.types.Scene.cgtmo
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
    _classes.clear()
