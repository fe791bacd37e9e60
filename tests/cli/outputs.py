#!/usr/bin/python3
"""What `cgtmo apply` writes besides pixels: colour profiles, bit depths, EXR compression, the
input's metadata, the double-tone-curve refusal and --json.

  outputs.py CGTMO_BINARY INPUTS_DIR WORK_DIR

The ICC profiles are parsed here from their bytes (ICC.1:2022 tag layout), independently of Little
CMS: the primaries and white are undone from the profile's chromatic adaptation (chad) and compared
with the published xy of each display; the curves are evaluated from their parameters and compared
with the sRGB formula and the 2.4 power law.
"""
import json
import os
import shutil
import struct
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

CGTMO, INPUTS, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
HERE = os.path.dirname(os.path.abspath(__file__))
CONFIG = os.path.join(HERE, "..", "..", "ocio_config", "config.ocio")
HDR = os.path.join(INPUTS, "hdr.exr")
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(*args):
    return subprocess.run([CGTMO, "apply", *args], capture_output=True, text=True)


def spec_of(path):
    i = oiio.ImageInput.open(path)
    assert i, oiio.geterror()
    s = i.spec()
    i.close()
    return s


# --- ICC parsing -------------------------------------------------------------------------------

def s15(b, off):
    return struct.unpack(">i", b[off:off + 4])[0] / 65536.0


def tags(icc):
    n = struct.unpack(">I", icc[128:132])[0]
    out = {}
    for k in range(n):
        sig, off, size = struct.unpack(">4sII", icc[132 + 12 * k:144 + 12 * k])
        out[sig.decode("latin-1")] = icc[off:off + size]
    return out


def xyz(tag):
    assert tag[:4] == b"XYZ ", tag[:4]
    return np.array([s15(tag, 8), s15(tag, 12), s15(tag, 16)])


def curve(tag):
    """The decoding function of a 'curv' or 'para' tag."""
    kind = tag[:4]
    if kind == b"curv":
        n = struct.unpack(">I", tag[8:12])[0]
        if n == 0:
            return lambda x: x
        if n == 1:
            g = struct.unpack(">H", tag[12:14])[0] / 256.0
            return lambda x: x ** g
        table = np.array(struct.unpack(">%dH" % n, tag[12:12 + 2 * n])) / 65535.0
        return lambda x: np.interp(x, np.linspace(0, 1, n), table)
    assert kind == b"para", kind
    ftype = struct.unpack(">H", tag[8:10])[0]
    count = {0: 1, 1: 3, 2: 4, 3: 5, 4: 7}[ftype]
    p = [s15(tag, 12 + 4 * i) for i in range(count)] + [0.0] * 7
    g, a, b, c, d, e, f = p[:7]
    if ftype == 0:
        return lambda x: x ** g
    if ftype == 1:
        return lambda x: np.where(x >= -b / a, np.maximum(a * x + b, 0) ** g, 0)
    if ftype == 2:
        return lambda x: np.where(x >= -b / a, np.maximum(a * x + b, 0) ** g + c, c)
    if ftype == 3:
        return lambda x: np.where(x >= d, np.maximum(a * x + b, 0) ** g, c * x)
    return lambda x: np.where(x >= d, np.maximum(a * x + b, 0) ** g + e, c * x + f)


def profile_facts(icc):
    t = tags(icc)
    chad = np.array([s15(t["chad"], 8 + 4 * i) for i in range(9)]).reshape(3, 3) if "chad" in t else np.eye(3)
    undo = np.linalg.inv(chad)
    def xy(v):
        v = undo @ v
        return v[:2] / v.sum()
    prim = [xy(xyz(t[k])) for k in ("rXYZ", "gXYZ", "bXYZ")]
    white = xy(xyz(t["wtpt"])) if icc[8] < 4 else xy(xyz(t["rXYZ"]) + xyz(t["gXYZ"]) + xyz(t["bXYZ"]))
    return prim, white, [curve(t[k]) for k in ("rTRC", "gTRC", "bTRC")]


def srgb_decode(e):
    return np.where(e <= 0.04045, e / 12.92, ((e + 0.055) / 1.055) ** 2.4)


REC709 = [(0.64, 0.33), (0.30, 0.60), (0.15, 0.06)]
P3 = [(0.680, 0.320), (0.265, 0.690), (0.150, 0.060)]
D65 = (0.3127, 0.3290)
E = np.linspace(0, 1, 257)


def check_profile(path, primaries, decode, what):
    s = spec_of(path)
    icc = s.getattribute("ICCProfile")
    if icc is None:
        check(False, f"{what}: has an ICC profile")
        return
    icc = bytes(np.asarray(icc, dtype=np.uint8))
    prim, white, trcs = profile_facts(icc)
    check(all(np.allclose(p, q, atol=2e-3) for p, q in zip(prim, primaries)), f"{what}: primaries {np.round(prim, 4).tolist()}")
    check(np.allclose(white, D65, atol=2e-3), f"{what}: white D65 ({np.round(white, 4).tolist()})")
    worst = max(float(np.max(np.abs(t(E) - decode(E)))) for t in trcs)
    check(worst < 2e-3, f"{what}: curve within 2e-3 of the display's (worst {worst:.2e})")


def fresh(name):
    p = os.path.join(WORK, name)
    if os.path.exists(p):
        os.remove(p)
    return p


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)

    # 1. Colour profiles.
    cases = [("sRGB", "srgb.png", REC709, srgb_decode), ("Display P3", "p3.png", P3, srgb_decode),
             ("Rec.1886", "rec1886.png", REC709, lambda e: e ** 2.4), ("Display P3", "p3.tif", P3, srgb_decode),
             ("Display P3", "p3.jpg", P3, srgb_decode)]
    for display, name, prim, decode in cases:
        out = fresh(name)
        p = run(HDR, "-o", out, "--op", "agx", "--display", display, "-q")
        check(p.returncode == 0 and p.stderr.count("profile") == 0, f"{display} -> {name}: exit 0, no profile warning")
        check_profile(out, prim, decode, f"{display} {name}")
    again = fresh("p3_again.png")
    run(HDR, "-o", again, "--op", "agx", "--display", "Display P3", "-q")
    first = np.asarray(spec_of(os.path.join(WORK, "p3.png")).getattribute("ICCProfile"), np.uint8)
    second = np.asarray(spec_of(again).getattribute("ICCProfile"), np.uint8)
    check(first.tobytes() == second.tobytes() and not first[84:100].any(),
          "the profile's bytes are the same in two runs (fixed header date, no ID)")
    out = fresh("default.png")
    run(HDR, "-o", out, "--op", "agx", "-q")
    check_profile(out, REC709, srgb_decode, "default display (sRGB)")
    out = fresh("linear.png")
    run(HDR, "-o", out, "--op", "agx", "--no-display", "-q")
    check_profile(out, REC709, lambda e: e, "--no-display png (linear Rec.709)")
    out = fresh("linear.exr")
    run(HDR, "-o", out, "--op", "agx", "--no-display", "-q")
    s = spec_of(out)
    ch = s.getattribute("chromaticities")
    check(ch is not None and np.allclose(ch, [0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290], atol=1e-4),
          f"--no-display exr: Rec.709/D65 chromaticities ({ch})")
    out = fresh("encoded.exr")
    run(HDR, "-o", out, "--op", "agx", "-q")
    check(spec_of(out).getattribute("chromaticities") is None, "display-encoded exr: no linear chromaticities claimed")
    # A display whose colour space is not a matrix and one curve (channels with different powers).
    foreign = os.path.join(WORK, "foreign.ocio")
    with open(foreign, "w") as f:
        f.write("""ocio_profile_version: 2
roles: {default: lin, scene_linear: lin}
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  Odd:
    - !<View> {name: Standard, colorspace: odd}
  Gamma22:
    - !<View> {name: Standard, colorspace: g22}
    - !<View> {name: Film, colorspace: g22, looks: hable}
looks:
  - !<Look> {name: hable, process_space: lin, transform: !<ExponentTransform> {value: 1.1}}
colorspaces:
  - !<ColorSpace> {name: lin, isdata: false}
  - !<ColorSpace> {name: odd, isdata: false, from_scene_reference: !<ExponentTransform> {value: [2.4, 2.2, 2.6, 1], direction: inverse}}
  - !<ColorSpace> {name: g22, isdata: false, from_scene_reference: !<ExponentTransform> {value: 2.2, direction: inverse}}
""")
    out = fresh("odd.png")
    p = run(HDR, "-o", out, "--op", "agx", "--colorconfig", foreign, "--display", "Odd", "-q")
    warn = [l for l in p.stderr.splitlines() if "profile" in l]
    check(p.returncode == 0 and len(warn) == 1 and "Odd/Standard" in warn[0], f"unknown encoding: one warning ({warn})")
    check(os.path.exists(out) and spec_of(out).getattribute("ICCProfile") is None, "unknown encoding: no profile written")
    out = fresh("g22.png")
    p = run(HDR, "-o", out, "--op", "agx", "--colorconfig", foreign, "--display", "Gamma22", "-q")
    check(p.returncode == 0 and "profile" not in p.stderr, "foreign config, pure 2.2 gamma: no warning")
    check_profile(out, REC709, lambda e: e ** 2.2, "foreign config gamma 2.2")

    # 2. Bit depths and compression.
    out8, out16 = fresh("d8.png"), fresh("d16.png")
    run(HDR, "-o", out8, "--op", "hable", "-q")
    p = run(HDR, "-o", out16, "--op", "hable", "--bit-depth", "16", "-q")
    check(p.returncode == 0 and spec_of(out16).format == oiio.UINT16, "--bit-depth 16 png: 16-bit PNG")
    a = oiio.ImageBuf(out8).get_pixels(oiio.FLOAT)
    b = oiio.ImageBuf(out16).get_pixels(oiio.FLOAT)
    diff = float(np.max(np.abs(a - b))) * 255
    check(diff <= 0.5 + 1e-3, f"16-bit PNG rounds to the 8-bit one (max {diff:.3f} code values)")
    check(len(np.unique(b[..., 0])) > len(np.unique(a[..., 0])), "16-bit PNG holds more levels than the 8-bit one")
    out = fresh("half.exr")
    p = run(HDR, "-o", out, "--op", "hable", "--bit-depth", "half", "--compression", "dwaa", "--no-display", "-q")
    s = spec_of(out)
    check(p.returncode == 0 and s.format == oiio.HALF, "--bit-depth half exr: half")
    check(s.getattribute("compression") == "dwaa", f"--compression dwaa (linear): {s.getattribute('compression')}")
    out = fresh("float.exr")
    run(HDR, "-o", out, "--op", "hable", "--compression", "piz", "-q")
    s = spec_of(out)
    check(s.format == oiio.FLOAT and s.getattribute("compression") == "piz", "exr default float, --compression piz")
    out = fresh("f.tif")
    p = run(HDR, "-o", out, "--op", "hable", "--bit-depth", "float", "-q")
    check(p.returncode == 0 and spec_of(out).format == oiio.FLOAT, "--bit-depth float tif")
    for args, text in [(["-o", os.path.join(WORK, "x.jpg"), "--bit-depth", "16"], "bit depth '16'"),
                       (["-o", os.path.join(WORK, "x.png"), "--bit-depth", "half"], "bit depth 'half'"),
                       (["-o", os.path.join(WORK, "x.exr"), "--bit-depth", "8"], "bit depth '8'"),
                       (["-o", os.path.join(WORK, "x.png"), "--compression", "zip"], "exr outputs only"),
                       (["-o", os.path.join(WORK, "x.exr"), "--compression", "lzma"], "unknown EXR compression 'lzma'"),
                       (["-o", os.path.join(WORK, "x.exr"), "--compression", "dwab"], "decodes display-encoded values outside [0, 1]")]:
        p = run(HDR, *args)
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        check(p.returncode == 2 and len(lines) == 1 and text in lines[0] and not os.path.exists(args[1]),
              f"refused {' '.join(args[2:])}: {lines}")

    # A sequence records a non-default bit depth: changing it redoes the frames.
    seq = os.path.join(WORK, "seq")
    os.makedirs(seq)
    for i in (1, 2):
        shutil.copyfile(HDR, os.path.join(seq, f"s.000{i}.exr"))
    pattern_in, pattern_out = os.path.join(seq, "s.####.exr"), os.path.join(seq, "o.####.png")
    run(pattern_in, "-o", pattern_out, "--op", "hable", "-q")
    same = run(pattern_in, "-o", pattern_out, "--op", "hable", "--dry-run").stdout
    other = run(pattern_in, "-o", pattern_out, "--op", "hable", "--bit-depth", "16", "--dry-run").stdout
    check(same.count("skip") == 2 and other.count("todo") == 2 and "bit depth" in other,
          f"sequence: --bit-depth 16 redoes frames made at 8 ({other.strip()!r})")

    # 3. Metadata: descriptive attributes pass, pixel-describing ones do not.
    src = os.path.join(WORK, "meta.exr")
    spec = oiio.ImageSpec(16, 8, 3, oiio.FLOAT)
    spec.attribute("Software", "TestRenderer 1.0")
    spec.attribute("Artist", "A. Lighter")
    spec.attribute("Copyright", "Studio 2026")
    matrix = tuple(float(i) for i in range(16))
    spec.attribute("worldToCamera", oiio.TypeDesc("matrix"), matrix)
    spec.attribute("compression", "piz")
    spec.attribute("chromaticities", oiio.TypeDesc("float[8]"), (0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.077, 0.32168, 0.33767))
    spec.attribute("ImageDescription", "the renderer's own note")
    o = oiio.ImageOutput.create(src)
    o.open(src, spec)
    o.write_image(np.full((8, 16, 3), 0.5, np.float32))
    o.close()
    out = fresh("meta_out.exr")
    p = run(src, "-o", out, "--op", "reinhard", "--no-display", "-q")
    s = spec_of(out)
    check(p.returncode == 0, f"metadata input applies ({p.stderr.strip()})")
    check(s.getattribute("Software") == "TestRenderer 1.0" and s.getattribute("Artist") == "A. Lighter"
          and s.getattribute("Copyright") == "Studio 2026", "exr: Software, Artist, Copyright passed")
    m = s.getattribute("worldToCamera")
    check(m is not None and np.allclose(np.asarray(m).ravel(), matrix), "exr: worldToCamera matrix passed")
    check(s.getattribute("compression") == "zip", "exr: input's piz compression not passed (zip)")
    check(np.allclose(s.getattribute("chromaticities"), [0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290], atol=1e-4),
          "exr: input's AP0 chromaticities not passed (Rec.709 written)")
    check("cgtmo provenance" in (s.getattribute("ImageDescription") or ""), "exr: ImageDescription is cgtmo's record")
    out = fresh("meta_out.png")
    run(src, "-o", out, "--op", "reinhard", "-q")
    s = spec_of(out)
    check(s.getattribute("Software") == "TestRenderer 1.0" and s.getattribute("Artist") == "A. Lighter",
          "png: Software, Artist passed")
    check(s.getattribute("worldToCamera") is None, "png: no matrix (PNG cannot hold one)")
    for ext in ("tif", "jpg"):
        out = fresh("meta_out." + ext)
        run(src, "-o", out, "--op", "reinhard", "-q")
        s = spec_of(out)
        check(s.getattribute("Software") == "TestRenderer 1.0" and s.getattribute("Copyright") == "Studio 2026",
              f"{ext}: Software, Copyright passed")

    # 4. Two tone curves.
    p = run(HDR, "-o", fresh("dbl.png"), "--op", "reinhard", "--colorconfig", CONFIG, "--view", "agx")
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    check(p.returncode == 2 and len(lines) == 1 and "twice" in lines[0] and not os.path.exists(os.path.join(WORK, "dbl.png")),
          f"--op reinhard --view agx refused: {lines}")
    p = run(HDR, "-o", fresh("dbl.png"), "--op", "reinhard", "--colorconfig", CONFIG, "--view", "agx", "--allow-double", "-q")
    check(p.returncode == 0 and os.path.exists(os.path.join(WORK, "dbl.png")), "--allow-double accepts it")
    p = run(HDR, "-o", fresh("std.png"), "--op", "reinhard", "--colorconfig", CONFIG, "--view", "Standard", "-q")
    check(p.returncode == 0, "--view Standard of the same config is fine")
    p = run(HDR, "-o", fresh("lin.png"), "--op", "linear", "--colorconfig", CONFIG, "--view", "agx", "-q")
    check(p.returncode == 0, "--op linear before an operator view is one tone curve")
    p = run(HDR, "-o", fresh("pre_agx.png"), "--op", "cgtmo", "-p", "output=scene-linear", "--colorconfig", CONFIG, "--view", "agx")
    check(p.returncode == 0 and "twice" not in p.stderr and "clips" not in p.stderr,
          f"cgtmo output=scene-linear finished by the agx view: one tone curve, no warning ({p.stderr.strip()[-120:]})")
    p = run(HDR, "-o", fresh("pre_std.png"), "--op", "cgtmo", "-p", "output=scene-linear", "--colorconfig", CONFIG, "--view", "Standard")
    check(p.returncode == 0 and "clips scene-linear 4.0" in p.stderr, "cgtmo output=scene-linear through a clipping view: warned")
    p = run(HDR, "-o", fresh("disp_std.png"), "--op", "cgtmo", "--colorconfig", CONFIG, "--view", "Standard")
    check(p.returncode == 0 and "clips" not in p.stderr, "cgtmo's display output through Standard: no clipping warning")
    p = run(HDR, "-o", fresh("film.png"), "--op", "drago", "--colorconfig", foreign, "--display", "Gamma22", "--view", "Film")
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    check(p.returncode == 2 and len(lines) == 1 and "'hable'" in lines[0], f"a studio view whose look is an operator's: refused {lines}")

    # 5. --json.
    out = fresh("j.png")
    p = run(HDR, "-o", out, "--op", "drago", "-p", "b=0.8", "--exposure", "1", "--json")
    try:
        j = json.loads(p.stdout)
        ok = True
    except ValueError as e:
        j, ok = {}, False
    check(ok and p.stdout.count("\n") == 1, f"--json: stdout is one JSON object ({p.stdout[:80]!r})")
    check(j.get("input") == HDR and j.get("output") == out and j.get("width") == 96 and j.get("height") == 54,
          "--json: input, output, size")
    check(j.get("operator") == "drago" and j.get("parameters", {}).get("b") == 0.8 and j.get("exposure_ev") == 1.0,
          "--json: operator, parameters, exposure")
    check(j.get("parameters", {}).get("lw_max", 0) > 0 and "image_statistics" in j, "--json: resolved image-derived parameters")
    check(j.get("display") == "sRGB" and j.get("view") == "Standard" and j.get("config") == "built-in config"
          and j.get("layer") == "ViewLayer.Combined", "--json: display, view, config, layer")
    check(j.get("sanitized", {}).get("nan") == 1 and j.get("sanitized", {}).get("total") == 5, "--json: sanitised counts")
    t = j.get("timings_ms", {})
    check(all(k in t for k in ("read", "tone-map", "write", "total")) and t["total"] >= t["read"], "--json: stage timings")
    check(j.get("bit_depth") == "8" and "ICC" in (j.get("colour_tag") or ""), "--json: format and colour tag")
    out = fresh("jc.png")
    p = run(HDR, "-o", out, "--op", "cgtmo", "--json")
    try:
        j = json.loads(p.stdout)
    except ValueError:
        j = {}
    st = j.get("scene_statistics", {})
    check(st.get("lw_max_source") == "image maximum" and st.get("lw_a", 0) > 0 and st.get("lw_a_source"),
          "--json cgtmo: Lw_max, Lw_a and their sources")
    check(j.get("guide", {}).get("decisions") and j.get("guide", {}).get("filter") == "fast", "--json cgtmo: guide decisions")
    # A sequence: one object for the run, an entry per frame (a missing frame's failure included).
    for f in (1, 2, 4):
        shutil.copyfile(HDR, os.path.join(WORK, "seq.%04d.exr" % f))
    seq_in, seq_out = os.path.join(WORK, "seq.####.exr"), os.path.join(WORK, "seq.####.png")
    for f in (1, 2, 3, 4):
        if os.path.exists(os.path.join(WORK, "seq.%04d.png" % f)):
            os.remove(os.path.join(WORK, "seq.%04d.png" % f))

    def run_json(*extra):
        p = run(seq_in, "-o", seq_out, "--op", "agx", "--json", *extra)
        try:
            return p, json.loads(p.stdout)
        except ValueError:
            return p, {}

    p, j = run_json("--frames", "1-4")
    frames = {f.get("frame"): f for f in j.get("frames", [])}
    check(p.returncode == 1 and p.stdout.count("\n") == 1 and j.get("input") == seq_in and j.get("output") == seq_out
          and j.get("operator") == "agx", f"--json sequence: one object, patterns and operator (exit {p.returncode})")
    check(j.get("done") == 3 and j.get("failed") == 1 and sorted(frames) == [1, 2, 3, 4]
          and frames[3].get("status") == "failed" and "seq.0003.exr" in frames[3].get("error", "")
          and frames[1].get("status") == "done" and frames[1].get("ms", 0) > 0
          and frames[4].get("output") == os.path.join(WORK, "seq.0004.png") and os.path.exists(frames[4]["output"]),
          "--json sequence: counts and each frame's status, time, output or error")
    p, j = run_json("--frames", "1,2,4")
    check(p.returncode == 0 and j.get("skipped") == 3 and j.get("done") == 0
          and all(f.get("status") == "skipped" for f in j.get("frames", [])), "--json sequence rerun: every frame skipped")
    p = run(seq_in, "-o", seq_out, "--json", "--dry-run")
    check(p.returncode == 2 and "--dry-run" in p.stderr and not p.stdout, "--json with --dry-run: refused")

    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
