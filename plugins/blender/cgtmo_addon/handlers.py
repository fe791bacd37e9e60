"""Render handlers: every finished frame (F12 stills, `-f`, every frame of `-a`) is tone-mapped.

Blender calls render_pre/post/write from the render thread when it renders in the UI, so there the
handlers only save the frame's EXR and queue a job; a timer runs the queue on the main thread
(library call, Image loading, reports). Headless (`blender -b`), jobs run at once, because Blender
exits as soon as the render ends. A cancelled render drops its frame: nothing is written for it."""
import time

import bpy
from bpy.app.handlers import persistent

from . import messages, tonemap

suspended = False        # set while the add-on renders its own probe
_rendered = []           # frames finished (render_post) but not yet written by Blender
_queue = []              # (scene name, frame, source EXR) waiting for the main thread
_started = [0.0]         # time the current render started (to tell fresh output from old files)


def _active(scene):
    return not suspended and hasattr(scene, "cgtmo") and scene.cgtmo.enabled


def _fail(scene, frame, exc):
    messages.report("ERROR", "frame %d not tone-mapped: %s" % (frame, messages.describe(exc)), scene=scene)


def run_job(scene, frame, source):
    """Tone-maps one frame's EXR. Never raises: failures become one clear message."""
    try:
        out = tonemap.output_for(scene, source)
        rep = tonemap.tonemap_file(scene, source, out, frame)
        scene.cgtmo.last_output = out
        tonemap.show_result(out)
        # Fallbacks (a missing probe, sidecar or pass) make it a warning: the result is not what a
        # prepared scene gives.
        level = "WARNING" if rep.get("warnings") or rep.get("notes") else "INFO"
        messages.report(level, tonemap.describe_report(rep, out), scene=scene)
        for line in rep.get("explain", []):  # scene operators: statistics and guide decisions
            print("cgtmo:   " + line, flush=True)
        return out
    except Exception as e:  # noqa: BLE001 - shown to the user as one line, no traceback
        _fail(scene, frame, e)
        return None


def _drain_queue():
    while _queue:
        name, frame, source = _queue.pop(0)
        scene = bpy.data.scenes.get(name)
        if scene is not None:
            run_job(scene, frame, source)
    return None  # one-shot timer


def _submit(scene, frame, written, defer=None):
    """Saves the frame's EXR now (the Render Result holds this frame only now), then tone-maps it
    now (headless) or from the main-thread queue (defer; the UI, where this runs in the render
    thread)."""
    try:
        source = tonemap.source_for_frame(scene, frame, written)
    except Exception as e:  # noqa: BLE001
        _fail(scene, frame, e)
        return
    if defer is None:
        defer = not bpy.app.background
    if not defer:
        run_job(scene, frame, source)
    else:
        _queue.append((scene.name, frame, source))
        if not bpy.app.timers.is_registered(_drain_queue):
            bpy.app.timers.register(_drain_queue, first_interval=0.0)


@persistent
def on_render_pre(scene, *_):
    if _active(scene):
        _rendered.clear()
        _started[0] = time.time()


@persistent
def on_render_post(scene, *_):
    if _active(scene):
        _rendered.append(scene.frame_current)


@persistent
def on_render_write(scene, *_):
    if not _active(scene):
        return
    frame = scene.frame_current
    if frame in _rendered:
        _rendered.remove(frame)
    _submit(scene, frame, tonemap.written_file(scene, frame, _started[0]))


@persistent
def on_render_complete(scene, *_):
    # Frames that finished but that Blender did not write (F12 still, render(write_still=False)).
    if not _active(scene):
        return
    frames = list(_rendered)
    _rendered.clear()
    for frame in frames[-1:]:  # only the last one is still in the Render Result
        _submit(scene, frame, None)


@persistent
def on_render_cancel(scene, *_):
    if not _active(scene):
        return
    _rendered.clear()
    messages.report("WARNING", "render cancelled: frame %d was not tone-mapped; cgtmo wrote nothing for it"
                    % scene.frame_current, scene=scene)


_HANDLERS = (("render_pre", on_render_pre), ("render_post", on_render_post), ("render_write", on_render_write),
             ("render_complete", on_render_complete), ("render_cancel", on_render_cancel))


def register():
    for name, fn in _HANDLERS:
        lst = getattr(bpy.app.handlers, name)
        if fn not in lst:
            lst.append(fn)


def unregister():
    for name, fn in _HANDLERS:
        lst = getattr(bpy.app.handlers, name)
        if fn in lst:
            lst.remove(fn)
    _queue.clear()
    _rendered.clear()
