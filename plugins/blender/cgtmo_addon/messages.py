"""One place for what the user is told: the console (headless runs), the panel's status line,
and Blender's report area (through the cgtmo.report operator, from the main thread)."""
import bpy

PREFIX = "cgtmo"


def report(level, text, scene=None, operator=None):
    """level: 'INFO', 'WARNING' or 'ERROR'. Never raises."""
    print("%s: %s: %s" % (PREFIX, level.lower(), text), flush=True)
    try:
        if scene is not None and hasattr(scene, "cgtmo"):
            scene.cgtmo.last_message = text
            scene.cgtmo.last_level = level
    except Exception:
        pass  # read-only context (e.g. during a render): the console line above is enough
    if operator is not None:
        operator.report({level}, text)
    elif not bpy.app.background:
        try:
            bpy.ops.cgtmo.report(level=level, message=text)
        except Exception:
            pass


def describe(exc):
    """A one-line message for an exception: the library's own text for its errors."""
    text = str(exc).strip() or exc.__class__.__name__
    if isinstance(exc, (ValueError, OSError, RuntimeError)) or exc.__class__.__name__ in ("CgtmoError", "DataError"):
        return text.splitlines()[0]
    return "%s: %s" % (exc.__class__.__name__, text.splitlines()[0])
