#!/usr/bin/python3
"""Numerical checks of the rendered test scenes (run with Debian's /usr/bin/python3: numpy, OIIO).

    /usr/bin/python3 tests/scenes/check_scenes.py [FOLDER...] [--json OUT]

For every NAME.exr with a NAME.json beside it (default: every scene folder under tests/scenes):
  - luminance range: mean of the brightest and of the darkest 0.1 % of pixels and their ratio
    (all pixels, sky included), also after a 5x5 box filter (noise leaves single dark pixels at
    exactly 0), plus the 0.1/99.9 percentiles;
  - background fraction (Depth >= 1e9);
  - light groups: peak luminance of each Combined_<group> pass, and which are all zero;
  - the light groups' sum against Combined (largest relative difference of the frame sums);
  - for every emitter the sidecar says is in frame: the brightest of its directly visible pixels
    in the Emit pass (Emit non-zero and that emitter's group at least 99 % of it) against the
    sidecar's luminance: equal (within 1e-3) when a pixel is fully covered, never above;
  - scene constraints: sun-window ratio (5x5 box) >= 1e5; two-rooms Emit all zero (no emitter seen), its
    light's group not all zero, image maximum below the light's luminance; lit-box and dark-doorway
    (a bright view from a dark place): the image's log-average at least 3 times the probe's (solid-angle
    weighted over the probe's lit directions, luminance floored at 1e-4, as the library computes it).
Exits 1 when a constraint fails.
"""
import glob
import json
import os
import sys

import numpy as np
import OpenImageIO as oiio

Y = np.array([0.2126, 0.7152, 0.0722])


def read(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise SystemExit("cannot open " + path + ": " + oiio.geterror())
    spec = inp.spec()
    px = inp.read_image(0, 0, 0, spec.nchannels, "float").reshape(spec.height, spec.width, spec.nchannels)
    inp.close()
    names = list(spec.channelnames)
    return {n: px[:, :, i].astype(np.float64) for i, n in enumerate(names)}


def lum(ch, prefix):
    return Y[0] * ch[prefix + ".R"] + Y[1] * ch[prefix + ".G"] + Y[2] * ch[prefix + ".B"]


def box_ratio(L, k):
    """Brightest over darkest 0.1 % of the k x k box-filtered luminance: path-tracing noise leaves
    single pixels at 0 in the darkest regions, which makes the per-pixel ratio infinite."""
    P = np.pad(L, k // 2, mode="edge")
    S = sum(P[i:i + L.shape[0], j:j + L.shape[1]] for i in range(k) for j in range(k)) / (k * k)
    f = np.sort(S.ravel())
    n = max(1, int(round(f.size * 0.001)))
    return float(f[-n:].mean() / f[:n].mean()) if f[:n].mean() > 0 else float("inf")


def check(exr, sidecar):
    ch = read(exr)
    side = json.load(open(sidecar))
    vl = side["view_layer"]
    L = lum(ch, vl + ".Combined")
    flat = np.sort(L.ravel())
    k = max(1, int(round(flat.size * 0.001)))
    dark, bright = flat[:k].mean(), flat[-k:].mean()
    res = {
        "scene": side["scene"], "file": exr, "size": [L.shape[1], L.shape[0]], "samples": side["samples"],
        "render_seconds": side["render_seconds"],
        "lum_min": float(flat[0]), "lum_max": float(flat[-1]),
        "p0.1": float(np.percentile(flat, 0.1)), "p99.9": float(np.percentile(flat, 99.9)),
        "dark_0.1pct_mean": float(dark), "bright_0.1pct_mean": float(bright),
        "ratio_0.1pct": float(bright / dark) if dark > 0 else float("inf"),
        "zero_pixels": int((flat <= 0).sum()),
        "ratio_0.1pct_box5": box_ratio(L, 5),
        "background_fraction": float((ch[vl + ".Depth.Z"] >= 1e9).mean()),
    }
    groups = {}
    total = np.zeros(3)
    for light in side["lights"]:
        g = light["lightgroup"]
        p = vl + ".Combined_" + g
        gl = lum(ch, p)
        groups[g] = {"peak": float(gl.max()), "all_zero": bool(not np.any(gl != 0))}
        total += [ch[p + c].sum() for c in (".R", ".G", ".B")]
    comb = np.array([ch[vl + ".Combined" + c].sum() for c in (".R", ".G", ".B")])
    res["groups"] = groups
    res["groups_sum_vs_combined"] = float(np.max(np.abs(total - comb) / np.maximum(comb, 1e-30)))
    emit = lum(ch, vl + ".Emit")
    res["emit_max"] = float(emit.max())
    seen = []
    for light in side["lights"]:
        if not light.get("in_frame"):
            continue
        gl = lum(ch, vl + ".Combined_" + light["lightgroup"])
        mask = (emit > 0) & (gl >= 0.99 * emit)
        vals = np.sort(emit[mask])
        if vals.size == 0:
            seen.append({"name": light["name"], "sidecar": light["luminance"], "pixels": 0})
            continue
        # A fully covered pixel shows exactly the emitted radiance (emission is noise-free); a
        # partly covered one shows less. So the brightest emitter pixel must match the sidecar,
        # or, for an emitter smaller than a pixel, stay below it.
        peak = float(vals[-1])
        full = int((vals >= 0.999 * peak).sum())
        seen.append({"name": light["name"], "sidecar": light["luminance"], "pixels": int(vals.size),
                     "rendered_max": peak, "pixels_at_max": full, "rel_diff": peak / light["luminance"] - 1.0})
    res["visible_emitters"] = seen
    failures = []
    if side["scene"] == "sun-window" and not res["ratio_0.1pct_box5"] >= 1e5:
        failures.append("sun-window: brightest/darkest 0.1 %% ratio (5x5 box) %.3g < 1e5" % res["ratio_0.1pct_box5"])
    if side["scene"] == "two-rooms":
        if res["emit_max"] != 0:
            failures.append("two-rooms: an emitter is visible (Emit max %g)" % res["emit_max"])
        if all(g["all_zero"] for g in groups.values()):
            failures.append("two-rooms: every light group pass is zero")
        lights = [l for l in side["lights"] if l["type"] != "WORLD"]
        res["light_luminance"] = max(l["luminance"] for l in lights)
        res["light_over_image_max"] = res["light_luminance"] / res["lum_max"]
        if any(l.get("in_frame") for l in lights):
            failures.append("two-rooms: the sidecar says a light is in frame")
    if side["scene"] in ("lit-box", "dark-doorway"):
        probe = side.get("probe")
        pl = lum(read(os.path.join(os.path.dirname(exr), probe["file"])), vl + ".Combined") if probe else None
        if pl is None:
            failures.append("%s: no probe" % side["scene"])
        else:
            h = pl.shape[0]
            w = np.cos(np.pi / 2 - np.pi * (np.arange(h) + 0.5) / h)[:, None] * (pl > 1e-4)
            res["probe_log_average"] = float(np.exp((w * np.log(np.maximum(pl, 1e-4))).sum() / w.sum()))
            res["image_log_average"] = float(np.exp(np.mean(np.log(np.maximum(L, 1e-4)))))
            res["image_over_probe"] = res["image_log_average"] / res["probe_log_average"]
            if not res["image_over_probe"] >= 3:
                failures.append("%s: image log-average only %.3g times the probe's (want >= 3)"
                                % (side["scene"], res["image_over_probe"]))
    for s in seen:
        if s["pixels"] and s["rel_diff"] > 1e-3:
            failures.append("%s: emitter %s renders %.6g, above the sidecar's %.6g" %
                            (side["scene"], s["name"], s["rendered_max"], s["sidecar"]))
        s["verified"] = bool(s["pixels"] and abs(s["rel_diff"]) <= 1e-3)
    res["failures"] = failures
    return res


def main(argv):
    out_json = None
    if "--json" in argv:
        i = argv.index("--json")
        out_json = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    here = os.path.dirname(os.path.abspath(__file__))
    folders = argv or sorted(d for d in glob.glob(os.path.join(here, "*")) if os.path.isdir(d))
    results = []
    for folder in folders:
        for side in sorted(glob.glob(os.path.join(folder, "*.json"))):
            exr = side[:-5] + ".exr"
            if os.path.exists(exr):
                results.append(check(exr, side))
    bad = 0
    for r in results:
        print("%-15s %4dx%-4d %5d spp %7.1f s  lum [%.3g, %.3g]  0.1%%: dark %.3g bright %.3g ratio %.3g (5x5 box: %.3g)  zero px %d  bg %.3f"
              % (r["scene"], r["size"][0], r["size"][1], r["samples"], r["render_seconds"], r["lum_min"], r["lum_max"],
                 r["dark_0.1pct_mean"], r["bright_0.1pct_mean"], r["ratio_0.1pct"], r["ratio_0.1pct_box5"], r["zero_pixels"],
                 r["background_fraction"]))
        print("    groups: " + ", ".join("%s %s" % (g, "ALL ZERO" if v["all_zero"] else "peak %.3g" % v["peak"])
                                      for g, v in r["groups"].items())
              + "; sum vs Combined %.2g" % r["groups_sum_vs_combined"])
        for s in r["visible_emitters"]:
            if s["pixels"]:
                print("    emitter %-14s sidecar %.6g  brightest Emit pixel %.6g (%d of %d px there)  diff %+.2e  %s"
                      % (s["name"], s["sidecar"], s["rendered_max"], s["pixels_at_max"], s["pixels"], s["rel_diff"],
                         "verified" if s["verified"] else "below: no fully covered pixel"))
            else:
                print("    emitter %-14s sidecar %.6g  no directly visible pixel" % (s["name"], s["sidecar"]))
        if "light_luminance" in r:
            print("    light luminance %.4g, image max %.4g: ratio %.3g, Emit max %g"
                  % (r["light_luminance"], r["lum_max"], r["light_over_image_max"], r["emit_max"]))
        if "image_over_probe" in r:
            print("    log-average: image %.4g, probe %.4g: ratio %.3g"
                  % (r["image_log_average"], r["probe_log_average"], r["image_over_probe"]))
        for f in r["failures"]:
            print("    FAIL " + f)
            bad += 1
    if out_json:
        with open(out_json, "w") as f:
            json.dump(results, f, indent=1)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
