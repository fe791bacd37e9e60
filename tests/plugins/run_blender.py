"""Runs one Blender test script headless and checks its console: exit status 0, no Python
traceback anywhere (the add-on must report problems as one line), and the expected lines.

    run_blender.py --blender blender --script S --zip cgtmo_addon.zip --cgtmo CLI --work DIR
                   [--expect TEXT]...

Blender gets a private user folder (BLENDER_USER_SCRIPTS/CONFIG under DIR) so that installing
the add-on from the zip touches nothing of the user's."""
import argparse
import os
import shutil
import subprocess
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--blender", required=True)
    p.add_argument("--script", required=True)
    p.add_argument("--zip", required=True)
    p.add_argument("--cgtmo", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--expect", action="append", default=[])
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--ocio", default="", help="start Blender with OCIO set to this config")
    a = p.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    env = dict(os.environ)
    env["BLENDER_USER_SCRIPTS"] = os.path.join(a.work, "user", "scripts")
    env["BLENDER_USER_CONFIG"] = os.path.join(a.work, "user", "config")
    env.pop("OCIO", None)  # Blender's own config and cgtmo's built-in one, unless --ocio
    if a.ocio:
        env["OCIO"] = os.path.abspath(a.ocio)
    cmd = [a.blender, "-b", "--factory-startup", "--python-exit-code", "3", "--python", a.script, "--",
           "--zip", os.path.abspath(a.zip), "--cgtmo", os.path.abspath(a.cgtmo), "--work", os.path.abspath(a.work),
           "--blender", a.blender]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=a.timeout)
    out = proc.stdout + proc.stderr
    with open(os.path.join(a.work, "console.log"), "w") as f:
        f.write(out)
    sys.stdout.write(out)
    errors = []
    if proc.returncode != 0:
        errors.append("blender exited with %d" % proc.returncode)
    if "Traceback" in out:
        errors.append("a Python traceback reached the console")
    for text in a.expect:
        if text not in out:
            errors.append("expected on the console: %r" % text)
    if "TEST PASSED" not in out:
        errors.append("the script did not reach its end")
    for e in errors:
        print("FAIL:", e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
