#!/usr/bin/python3
"""Golden-file tests of the cgtmo command line, in the manner of OpenImageIO's testsuite: run the
tool, compare its output with a committed reference in ref/, within a stated tolerance.

The suite runs golden cases with --exact: every value equal to the reference's, since the tool's
outputs are the same bits on every x86-64 CPU (docs/numerics.md). Without it, the tolerances are for
another compiler or architecture: 8-bit outputs within 1 code value per channel, 16-bit TIFF within
1/255 of full scale, EXR within 1e-5 absolute + 1e-5 relative.
Bad-input cases check the exit code (2 usage, 1 data), a one-line error message naming the
problem, and that no output was created or modified.

  run_golden.py --cgtmo BIN --inputs DIR --work DIR [--case NAME] [--update]
  run_golden.py --cgtmo BIN --inputs DIR --work DIR --exact      (bit for bit)
  run_golden.py --list
--update rewrites ref/ from the current tool (review the diff before committing).

Which operators get a golden is the tool's registry (`cgtmo list --json`): every pixel operator
has the case op_<name> with the reference ref/<name>.png, and the case `registry` fails, saying how
to create it, when one has none; scene operators (they need a render's passes) are checked by the
quality table docs/quality.md, which must have a column for each.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "ref")
ROOT = os.path.dirname(os.path.dirname(HERE))
# Scene operators read a render's passes, which hdr.exr lacks: their end-to-end check is the
# quality table, regenerated from the committed scenes and compared by the test_quality_doc test.
QUALITY_DOC = os.path.join(ROOT, "docs", "quality.md")

# name -> (arguments after IN, output file name); IN is hdr.exr unless the args say otherwise.
# Besides these, every pixel operator of the registry has the case op_<name>: `--op <name>` with
# its defaults, reference ref/<name>.png (see golden_case).
GOLDEN = {
    "plain_rgb": (["@plain.exr", "--op", "reinhard"], "plain_reinhard.png"),
    "exposure": (["--op", "aces-narkowicz", "--exposure", "-2.5"], "narkowicz_ev-2.5.png"),
    "params": (["--op", "drago", "-p", "b=0.7", "-p", "lw_max=500", "-p", "mode=per-channel"], "drago_params.png"),
    "luminance_mode": (["--op", "hable", "-p", "mode=luminance", "-p", "saturation=0.8"], "hable_lum.png"),
    "display_p3": (["--op", "agx", "--display", "Display P3"], "agx_p3.png"),
    "rec1886": (["--op", "uchimura", "--display", "Rec.1886"], "uchimura_1886.png"),
    "tiff16": (["--op", "lottes"], "lottes.tif"),
    "linear_exr": (["--op", "reinhard-jodie", "--no-display"], "jodie_linear.exr"),
    "layer": (["--op", "reinhard", "--layer", "ViewLayer"], "layer_reinhard.png"),
}


def golden_case(name):
    """(arguments, output file name) of a golden case: GOLDEN's, or op_<operator>."""
    if name in GOLDEN:
        return GOLDEN[name]
    if name.startswith("op_"):
        op = name[3:]
        return ["--op", op], f"{op}.png"
    raise KeyError(f"no golden case {name!r}")


def referenced_operators():
    """The operators with a committed reference: ref/<op>.png that no other case writes. ctest
    registers its cases before the tool is built, so the per-operator cases come from here; the
    case `registry` checks them against the tool's own list."""
    others = {out for _, out in GOLDEN.values()}
    return sorted(f[:-4] for f in os.listdir(REF) if f.endswith(".png") and f not in others)


def registry(cgtmo):
    """The tool's operators as `cgtmo list --json` describes them."""
    p = subprocess.run([cgtmo, "list", "--json"], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"cgtmo list --json: exit {p.returncode}: {p.stderr.strip()}")
    return json.loads(p.stdout)


def quality_doc_columns():
    """The method columns of the committed quality table (its first table's header)."""
    for line in open(QUALITY_DOC, encoding="utf-8"):
        if line.startswith("| Scene |"):
            return [c.strip() for c in line.strip().strip("|").split("|")][2:]
    return []


def check_registry(cgtmo):
    """Every operator the tool lists has its golden: a pixel operator its reference image, a scene
    operator a column of the quality table; and every reference belongs to a listed operator."""
    ops = registry(cgtmo)
    errs = []
    pixel = [op["name"] for op in ops if op["scope"] == "pixel"]
    scene = [op["name"] for op in ops if op["scope"] == "scene"]
    if not pixel or not scene:
        errs.append(f"the registry lists {len(pixel)} pixel and {len(scene)} scene operators; expected both")
    here = os.path.relpath(HERE, ROOT)
    for op in pixel:
        if not os.path.exists(os.path.join(REF, f"{op}.png")):
            errs.append(f"operator '{op}' has no reference {os.path.join(here, 'ref', op + '.png')}: create it with "
                        f"/usr/bin/python3 {os.path.join(here, 'make_inputs.py')} INPUTS && /usr/bin/python3 "
                        f"{os.path.join(here, 'run_golden.py')} --cgtmo BUILD/apps/cgtmo/cgtmo --inputs INPUTS "
                        f"--work WORK --case golden_op_{op} --update, look at the image, commit it and re-run cmake "
                        f"(see {os.path.join(here, 'ref', 'README.md')})")
    for op in referenced_operators():
        if op not in pixel:
            errs.append(f"reference ref/{op}.png belongs to no pixel operator of `cgtmo list`: remove it")
    columns = quality_doc_columns()
    for op in scene:
        if not any(c == op or c.startswith(op + "-") for c in columns):
            errs.append(f"scene operator '{op}' has no column in docs/quality.md (columns: {', '.join(columns)}): "
                        "regenerate it with `cgtmo eval --scenes tests/scenes --write docs/quality.md`")
    return "; ".join(errs) or None


# name -> (arguments, expected exit code, text the error line must contain)
BAD = {
    "missing_file": (["@missing.exr", "-o", "{out}"], 1, "no such file"),
    "not_an_image": (["@notimage.exr", "-o", "{out}"], 1, "not an OpenEXR"),
    "truncated": (["@truncated.exr", "-o", "{out}"], 1, "truncated"),
    "corrupt": (["@corrupt.exr", "-o", "{out}"], 1, "corrupt"),
    "no_rgb_layer": (["@norgb.exr", "-o", "{out}"], 1, "no RGB layer"),
    "missing_layer": (["-o", "{out}", "--layer", "Nope"], 1, "no RGB layer 'Nope'"),
    "unknown_operator": (["-o", "{out}", "--op", "nope"], 2, "unknown operator 'nope'"),
    "unknown_param": (["-o", "{out}", "--op", "reinhard", "-p", "whiteish=2"], 2, "no parameter 'whiteish'"),
    "param_not_number": (["-o", "{out}", "--op", "hable", "-p", "white=abc"], 2, "needs a number"),
    "param_out_of_range": (["-o", "{out}", "--op", "drago", "-p", "b=3"], 2, "out of range"),
    "param_bad_choice": (["-o", "{out}", "--op", "reinhard", "-p", "mode=sideways"], 2, "is not one of"),
    "param_no_equals": (["-o", "{out}", "-p", "white"], 2, "not key=value"),
    "missing_folder": (["-o", "{work}/no/such/folder/out.png"], 2, "does not exist"),
    "out_is_in": (["-o", "@hdr.exr"], 2, "is the input"),
    "bad_extension": (["-o", "{work}/out.xyz"], 2, "unsupported extension"),
    "unknown_option": (["-o", "{out}", "--frobnicate"], 2, "frobnicate"),
    "unknown_display": (["-o", "{out}", "--display", "Nope"], 2, "display 'Nope'"),
    "unknown_view": (["-o", "{out}", "--view", "Nope"], 2, "view 'Nope'"),
    "bad_config": (["-o", "{out}", "--colorconfig", "@notimage.exr"], 2, "cannot load OCIO config"),
    "missing_camera_table": (["-o", "{out}", "--op", "camera", "-p", "table=@missing.dorf"], 1, "cannot read camera table"),
    "no_output": ([], 2, "output"),
}


def read(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        raise RuntimeError(buf.geterror())
    return buf.get_pixels(oiio.FLOAT), buf.spec()


def compare(out, ref, exact=False):
    a, sa = read(out)
    b, sb = read(ref)
    if a.shape != b.shape:
        return f"shape {a.shape} != reference {b.shape}"
    if exact:
        differ = np.count_nonzero((a != b) & ~(np.isnan(a) & np.isnan(b)))
        return f"{differ} values differ from the reference (exact comparison)" if differ else None
    ext = os.path.splitext(out)[1].lower()
    if ext == ".exr":
        err = np.abs(a - b) - (1e-5 + 1e-5 * np.abs(b))
        bad = np.count_nonzero(err > 0)
        return f"{bad} values differ beyond 1e-5 abs + 1e-5 rel" if bad else None
    scale = 255.0
    diff = np.abs(a - b) * scale
    worst = float(diff.max())
    return f"max difference {worst:.2f} code values (> 1)" if worst > 1.0 + 1e-3 else None


def expand(args, inputs, work, out):
    res = []
    for a in args:
        a = a.replace("{out}", out).replace("{work}", work)
        if "@" in a:
            pre, name = a.split("@", 1)
            a = pre + os.path.join(inputs, name)
        res.append(a)
    return res


def run_golden(name, cgtmo, inputs, work, update, exact=False):
    if name == "registry":
        return None if update else check_registry(cgtmo)
    args, out_name = golden_case(name)
    out = os.path.join(work, out_name)
    if os.path.exists(out):
        os.remove(out)
    infile = os.path.join(inputs, "hdr.exr")
    if args and args[0].startswith("@"):
        infile = os.path.join(inputs, args[0][1:])
        args = args[1:]
    cmd = [cgtmo, "apply", infile, "-o", out, "-q"] + expand(args, inputs, work, out)
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return f"exit {p.returncode}: {p.stderr.strip()}"
    ref = os.path.join(REF, out_name)
    if update:
        shutil.copyfile(out, ref)
        return None
    if not os.path.exists(ref):
        return f"no reference {ref} (run with --update)"
    return compare(out, ref, exact)


def run_bad(name, cgtmo, inputs, work):
    args, code, text = BAD[name]
    out = os.path.join(work, f"bad_{name}.png")
    # An existing output must survive a failing run untouched.
    with open(out, "wb") as f:
        f.write(b"previous output")
    cmd = [cgtmo, "apply"]
    if not (args and args[0].startswith("@")):
        cmd.append(os.path.join(inputs, "hdr.exr"))
    cmd += expand(args, inputs, work, out)
    before = set(os.listdir(work))
    p = subprocess.run(cmd, capture_output=True, text=True)
    errs = []
    if p.returncode != code:
        errs.append(f"exit {p.returncode}, expected {code}")
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    if len(lines) != 1:
        errs.append(f"expected one error line, got {len(lines)}: {p.stderr!r}")
    elif text not in lines[0]:
        errs.append(f"error line lacks {text!r}: {lines[0]!r}")
    if open(out, "rb").read() != b"previous output":
        errs.append("existing output was modified")
    after = set(os.listdir(work))
    if after - before:
        errs.append(f"files left behind: {sorted(after - before)}")
    for f in os.listdir(inputs):
        if ".cgtmo-tmp" in f:
            errs.append(f"temporary left in inputs: {f}")
    os.remove(out)
    return "; ".join(errs) or None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cgtmo")
    ap.add_argument("--inputs")
    ap.add_argument("--work")
    ap.add_argument("--case", action="append")
    ap.add_argument("--update", action="store_true")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--exact", action="store_true",
                    help="golden cases: every pixel value equal to the reference's (the references are the "
                         "same bits on every CPU; scripts/check-reproducible.sh)")
    a = ap.parse_args()
    golden = [f"op_{op}" for op in referenced_operators()] + list(GOLDEN) + ["registry"]
    if a.list:
        print(";".join([f"golden_{n}" for n in golden] + [f"bad_{n}" for n in BAD]))
        return 0
    if not a.case:
        # Every operator the tool lists, whether or not it has a reference yet.
        ops = [f"op_{op['name']}" for op in registry(a.cgtmo) if op["scope"] == "pixel"]
        golden = ops + [n for n in golden if not n.startswith("op_")]
    names = [f"golden_{n}" for n in golden] + [f"bad_{n}" for n in BAD]
    os.makedirs(a.work, exist_ok=True)
    failed = 0
    for n in a.case or names:
        kind, case = n.split("_", 1)
        err = run_golden(case, a.cgtmo, a.inputs, a.work, a.update, a.exact) if kind == "golden" else run_bad(case, a.cgtmo, a.inputs, a.work)
        print(f"{'FAIL' if err else 'ok  '} {n}" + (f": {err}" if err else ""))
        failed += bool(err)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
