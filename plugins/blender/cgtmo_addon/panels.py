"""The Render Properties panel: operator and its registry parameters, output encoding, Prepare
scene, and Blender's own OCIO view and look (which list our config's when Blender is started
with OCIO=ocio_config/config.ocio, docs/plugins.md)."""
import os

import bpy

from . import engine, properties


class CGTMO_PT_render(bpy.types.Panel):
    bl_label = "cgtmo Tone Mapping"
    bl_idname = "CGTMO_PT_render"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "render"

    def draw_header(self, context):
        self.layout.prop(context.scene.cgtmo, "enabled", text="")

    def draw(self, context):
        layout = self.layout
        s = context.scene.cgtmo
        try:
            engine.lib()
        except engine.CgtmoError as e:
            layout.label(text=str(e), icon="ERROR")
            return
        layout.use_property_split = True
        layout.prop(s, "operator")
        group = properties.param_group(s, s.operator)
        specs = properties.param_specs(s.operator)
        if engine.is_scene_operator(s.operator):
            layout.label(text="Reads the scene: run Prepare scene before rendering", icon="INFO")
        if group is not None and specs:
            col = layout.column(align=True)
            for p in specs:
                if p.get("default_from"):
                    row = col.row(align=True)
                    row.prop(group, p["name"] + "_auto", text=p["name"] + " from image")
                    sub = row.row(align=True)
                    sub.enabled = not getattr(group, p["name"] + "_auto")
                    sub.prop(group, p["name"], text="")
                else:
                    col.prop(group, p["name"])
        layout.prop(s, "exposure")

        box = layout.box()
        box.label(text="Written image")
        box.prop(s, "output_format")
        box.prop(s, "color_config")
        box.prop(s, "input_colorspace")
        box.prop(s, "display")
        box.prop(s, "view")

        box = layout.box()
        box.label(text="Blender display (OCIO: %s)" % (os.environ.get("OCIO") or "Blender's config"))
        box.prop(context.scene.view_settings, "view_transform")
        box.prop(context.scene.view_settings, "look")

        col = layout.column()
        if engine.is_scene_operator(s.operator):
            col.prop(s, "prepare_frames")
            col.prop(s, "probe_samples")
        row = col.row(align=True)
        row.operator("cgtmo.prepare_scene", icon="SCENE_DATA")
        row.operator("cgtmo.tonemap_render", icon="IMAGE_DATA")
        if s.last_message:
            icon = {"ERROR": "ERROR", "WARNING": "ERROR"}.get(s.last_level, "INFO")
            col.label(text=s.last_message, icon=icon)


_classes = (CGTMO_PT_render,)


# Blender's own helper: registers in order, unregisters in reverse.
register, unregister = bpy.utils.register_classes_factory(_classes)
