"""Operators: Prepare scene, Tone-map last render, and the report helper the handlers use to reach
Blender's report area from the main thread."""
import bpy
from bpy.props import EnumProperty, StringProperty

from . import handlers, messages, properties, scene_prep


class CGTMO_OT_prepare_scene(bpy.types.Operator):
    """Enable the passes the chosen operator needs, one light group per emitter and the world,
    multilayer EXR output, and write the 64x32 probe and the JSON sidecar"""
    bl_idname = "cgtmo.prepare_scene"
    bl_label = "Prepare scene"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        scene = context.scene
        s = scene.cgtmo
        try:
            notes, _ = scene_prep.prepare(scene, s.operator, properties.chosen_params(s), s.prepare_frames,
                                          s.probe_samples)
        except Exception as e:  # noqa: BLE001 - one line in the report area, no traceback
            messages.report("ERROR", "Prepare scene: " + messages.describe(e), scene=scene, operator=self)
            return {"CANCELLED"}
        for n in notes[:-1]:
            messages.report("WARNING", n, scene=scene, operator=self)
        messages.report("INFO", notes[-1], scene=scene, operator=self)
        return {"FINISHED"}


class CGTMO_OT_tonemap_render(bpy.types.Operator):
    """Tone-map the current Render Result now with the chosen operator (saved as NAME.exr first)"""
    bl_idname = "cgtmo.tonemap_render"
    bl_label = "Tone-map last render"

    def execute(self, context):
        scene = context.scene
        frame = scene.frame_current
        try:
            source = handlers.tonemap.source_for_frame(scene, frame)
        except Exception as e:  # noqa: BLE001
            messages.report("ERROR", messages.describe(e), scene=scene, operator=self)
            return {"CANCELLED"}
        out = handlers.run_job(scene, frame, source)
        return {"FINISHED"} if out else {"CANCELLED"}


class CGTMO_OT_report(bpy.types.Operator):
    """Show a cgtmo message in Blender's report area"""
    bl_idname = "cgtmo.report"
    bl_label = "cgtmo message"
    bl_options = {"INTERNAL"}

    level: EnumProperty(items=[("INFO", "Info", ""), ("WARNING", "Warning", ""), ("ERROR", "Error", "")])
    message: StringProperty()

    def execute(self, context):
        self.report({self.level}, self.message)
        return {"FINISHED"}


_classes = (CGTMO_OT_prepare_scene, CGTMO_OT_tonemap_render, CGTMO_OT_report)


# Blender's own helper: registers in order, unregisters in reverse.
register, unregister = bpy.utils.register_classes_factory(_classes)
