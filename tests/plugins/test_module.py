"""Tests of the `cgtmo` Python module (plugins/python), run by ctest with /usr/bin/python3:
    PYTHONPATH=<build>/python /usr/bin/python3 tests/plugins/test_module.py --cgtmo <build>/apps/cgtmo/cgtmo

Expected values come from the published formulas written here in numpy, or from the `cgtmo`
command line (the module must give the very same pixels as `cgtmo apply`)."""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import OpenImageIO as oiio

import cgtmo

CLI = None  # path of the cgtmo tool, from --cgtmo


def srgb_encode(x):
    """IEC 61966-2-1 sRGB OETF."""
    x = np.clip(x, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)


def write_exr(path, pixels, names=None):
    h, w, c = pixels.shape
    spec = oiio.ImageSpec(w, h, c, oiio.FLOAT)
    if names:
        spec.channelnames = tuple(names)
    out = oiio.ImageOutput.create(path)
    out.open(path, spec)
    out.write_image(pixels)
    out.close()


def read_image(path):
    # ImageInput, not ImageBuf: an ImageBuf reads through OIIO's shared ImageCache, which hands back
    # the old pixels of a file rewritten under the same name within its timestamp's resolution (the
    # subtests below write py.png one after another).
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise OSError("cannot read %s: %s" % (path, oiio.geterror()))
    try:
        return inp.read_image(oiio.UINT8 if path.endswith(".png") else oiio.FLOAT)
    finally:
        inp.close()


def test_image(h=24, w=40, seed=1):
    """A deterministic HDR image from 1e-3 to about 200, grey and saturated pixels."""
    rng = np.random.default_rng(seed)
    img = np.exp(rng.uniform(math.log(1e-3), math.log(200.0), size=(h, w, 3))).astype(np.float32)
    img[0, :4] = [[0, 0, 0], [1, 1, 1], [0.18, 0.18, 0.18], [4, 0.01, 0.01]]
    return img


def addon_engine():
    """The Blender add-on's engine module (plugins/blender/cgtmo_addon/engine.py), loaded without
    Blender: it needs only the cgtmo module (its bundled copy is absent here, so the one on
    PYTHONPATH serves)."""
    import importlib.util
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plugins", "blender", "cgtmo_addon",
                        "engine.py")
    spec = importlib.util.spec_from_file_location("cgtmo_addon.engine", path)
    engine = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(engine)
    return engine


class Registry(unittest.TestCase):
    def test_same_catalogue_in_cli_module_and_addon(self):
        """One registry, three faces: `cgtmo list --json`, cgtmo.operators() and the add-on's
        catalogue list the same operators in the same order, every field equal."""
        cli = json.loads(subprocess.run([CLI, "list", "--json"], check=True, capture_output=True, text=True).stdout)
        module = cgtmo.operators()
        addon = addon_engine().catalogue()
        names = [o["name"] for o in cli]
        self.assertEqual(names, [o["name"] for o in module])
        self.assertEqual(names, [o["name"] for o in addon])
        for a, b, c in zip(cli, module, addon):
            self.assertEqual(sorted(a), sorted(b), a["name"])
            self.assertEqual(sorted(a), sorted(c), a["name"])
            for key in a:
                self.assertEqual(a[key], b[key], (a["name"], key))
                self.assertEqual(a[key], c[key], (a["name"], key))
            self.assertEqual(cgtmo.operator(a["name"]), b)
        # The spellings every face shares.
        self.assertEqual([o["name"] for o in cli if o["scope"] == "scene"], ["cgtmo", "wls"])
        self.assertEqual({o["scope"] for o in cli}, {"pixel", "scene"})
        self.assertEqual({o["kind"] for o in cli}, {"per-channel", "mixing"})
        sources = {p["default_from"] for o in cli for p in o["params"] if "default_from" in p}
        self.assertEqual(sources, {"max_channel", "max_luminance", "log_average_luminance"})
        drago = next(o for o in cli if o["name"] == "drago")
        self.assertEqual(next(p for p in drago["params"] if p["name"] == "lw_max")["default_from"], "max_luminance")
        # The add-on asks the same registry which operators read the scene.
        engine = addon_engine()
        self.assertEqual([n for n in names if engine.is_scene_operator(n)], ["cgtmo", "wls"])


class ApplyArray(unittest.TestCase):
    def test_reinhard_linear_matches_formula(self):
        img = test_image()
        out = cgtmo.apply(img, op="reinhard", encode=False)
        self.assertEqual(out.dtype, np.float32)
        self.assertEqual(out.shape, img.shape)
        np.testing.assert_allclose(out, img / (1.0 + img), rtol=1e-6, atol=1e-7)

    def test_exposure_then_srgb_display(self):
        img = test_image()
        out = cgtmo.apply(img, op="reinhard", exposure=-1.5)
        x = img.astype(np.float64) * 2.0 ** -1.5
        np.testing.assert_allclose(out, srgb_encode(x / (1.0 + x)), atol=2e-4)

    def test_input_untouched_and_alpha_passes(self):
        img = np.concatenate([test_image(), np.full((24, 40, 1), 0.25, np.float32)], axis=2)
        before = img.copy()
        out = cgtmo.apply(img, op="aces-narkowicz")
        np.testing.assert_array_equal(img, before)
        np.testing.assert_array_equal(out[..., 3], 0.25)

    def test_float64_and_noncontiguous_input(self):
        img = test_image()
        a = cgtmo.apply(img.astype(np.float64), op="hable")
        b = cgtmo.apply(np.ascontiguousarray(img[:, ::-1])[:, ::-1], op="hable")
        c = cgtmo.apply(img, op="hable")
        np.testing.assert_array_equal(a, c)
        np.testing.assert_array_equal(b, c)

    def test_nonfinite_policy_reported(self):
        img = test_image()
        img[1, 1] = [np.nan, np.inf, -1.0]
        out, rep = cgtmo.apply(img, op="reinhard", encode=False, report=True)
        self.assertTrue(np.isfinite(out).all())
        # NaN -> 0, +Inf -> 65504, negative -> 0 (docs/numerics.md)
        np.testing.assert_allclose(out[1, 1], [0.0, 65504.0 / 65505.0, 0.0], rtol=1e-6)
        self.assertEqual(len(rep["warnings"]), 1)
        self.assertIn("NaN", rep["warnings"][0])

    def test_image_default_params_in_report(self):
        img = test_image()
        _, rep = cgtmo.apply(img, op="drago", report=True)
        lum = 0.2126 * img[..., 0].astype(np.float64) + 0.7152 * img[..., 1] + 0.0722 * img[..., 2]
        self.assertAlmostEqual(rep["params"]["lw_max"], lum.max(), delta=1e-4 * lum.max())
        self.assertEqual(rep["display"], "sRGB")
        self.assertEqual(rep["view"], "Standard")

    def test_bad_arrays(self):
        for bad in (np.zeros((4, 4), np.float32), np.zeros((4, 4, 2), np.float32), np.zeros((0, 4, 3), np.float32)):
            with self.assertRaises(ValueError):
                cgtmo.apply(bad, op="reinhard")
        with self.assertRaises(ValueError):
            cgtmo.apply(test_image(), op="reinhard", params={"nope": 1})
        with self.assertRaises(ValueError):
            cgtmo.apply(test_image(), op="reinhard", display="No Such Display")
        with self.assertRaises(ValueError):
            cgtmo.apply(test_image(), exposure=float("nan"))

    def test_integer_arrays_are_display_referred_and_refused(self):
        for dtype in (np.uint8, np.uint16, np.int32):
            with self.subTest(dtype=dtype):
                with self.assertRaises(ValueError) as e:
                    cgtmo.apply(np.full((4, 4, 3), 128, dtype), op="agx")
                self.assertIn("display-referred", str(e.exception))


class ApplyFile(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.exr = os.path.join(self.dir, "render.exr")
        img = test_image(32, 48)
        alpha = np.ones((32, 48, 1), np.float32)
        write_exr(self.exr, np.concatenate([img, alpha], axis=2),
                  ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A"])
        self.img = img

    def tearDown(self):
        self.tmp.cleanup()

    def cli(self, *args):
        return subprocess.run([CLI, "apply", *args], capture_output=True, text=True)

    def test_same_pixels_as_cli(self):
        cases = [("drago", {}, 0.0, "png"), ("aces-narkowicz", {}, 1.0, "png"), ("drago", {"b": 0.7}, -0.5, "tif"),
                 ("agx", {}, 0.0, "exr"), ("hable", {}, 0.0, "png")]
        for op, params, ev, ext in cases:
            with self.subTest(op=op, ext=ext):
                mine = os.path.join(self.dir, "py_%s.%s" % (op, ext))
                theirs = os.path.join(self.dir, "cli_%s.%s" % (op, ext))
                rep = cgtmo.apply_file(self.exr, mine, op=op, params=params, exposure=ev)
                args = [self.exr, "-o", theirs, "--op", op, "--exposure", repr(ev), "-q"]
                for k, v in params.items():
                    args += ["-p", "%s=%r" % (k, v)]
                p = self.cli(*args)
                self.assertEqual(p.returncode, 0, p.stderr)
                np.testing.assert_array_equal(read_image(mine), read_image(theirs))
                self.assertEqual(rep["layer"], "ViewLayer.Combined")
                self.assertEqual((rep["width"], rep["height"], rep["channels"]), (48, 32, 4))

    def test_an_8_bit_png_is_decoded_from_srgb_with_a_warning(self):
        png = os.path.join(self.dir, "grey.png")
        buf = oiio.ImageBuf(oiio.ImageSpec(8, 4, 3, oiio.UINT8))
        oiio.ImageBufAlgo.fill(buf, (0.5, 0.5, 0.5))
        self.assertTrue(buf.write(png))
        out = os.path.join(self.dir, "grey-out.png")
        rep = cgtmo.apply_file(png, out, op="linear")
        # Decoded, clipped by nothing, encoded again: the code values come back.
        self.assertLessEqual(np.abs(read_image(out) * 255 - 128).max(), 1.0)
        self.assertTrue(any("display-referred" in w for w in rep["warnings"]), rep["warnings"])

    def test_array_and_file_agree(self):
        out = os.path.join(self.dir, "lin.exr")
        cgtmo.apply_file(self.exr, out, op="uchimura", encode=False)
        from_file = read_image(out)[..., :3]
        from_array = cgtmo.apply(self.img, op="uchimura", encode=False)
        np.testing.assert_array_equal(from_file, from_array)

    def test_file_bit_depth_and_compression_as_the_cli(self):
        for name, kw, args in (("p16.png", {"bit_depth": "16"}, ("--bit-depth", "16")),
                               ("h.exr", {"bit_depth": "half", "compression": "piz", "encode": False},
                                ("--bit-depth", "half", "--compression", "piz", "--no-display"))):
            mine, theirs = os.path.join(self.dir, "py-" + name), os.path.join(self.dir, "cli-" + name)
            cgtmo.apply_file(self.exr, mine, op="agx", **kw)
            p = self.cli(self.exr, "-o", theirs, "--op", "agx", "-q", *args)
            self.assertEqual(p.returncode, 0, p.stderr)
            a, b = oiio.ImageInput.open(mine), oiio.ImageInput.open(theirs)
            self.assertEqual(str(a.spec().format), str(b.spec().format))
            self.assertEqual(a.spec().getattribute("compression"), b.spec().getattribute("compression"))
            self.assertEqual(str(a.spec().format), "uint16" if name.endswith(".png") else "half")
            a.close()
            b.close()
            np.testing.assert_array_equal(read_image(mine), read_image(theirs))
        with self.assertRaises(ValueError):  # PNG has no half
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.png"), bit_depth="half")
        with self.assertRaises(ValueError):  # compression is EXR's
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.png"), compression="piz")
        with self.assertRaises(ValueError):  # DWA decodes display-encoded values outside [0, 1], as the CLI says
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.exr"), compression="dwaa")
        self.assertFalse(os.path.exists(os.path.join(self.dir, "x.exr")))

    def test_errors_write_nothing(self):
        before = sorted(os.listdir(self.dir))
        with self.assertRaises(cgtmo.DataError) as e:
            cgtmo.apply_file(os.path.join(self.dir, "missing.exr"), os.path.join(self.dir, "x.png"))
        self.assertIsInstance(e.exception, OSError)
        self.assertIn("missing.exr", str(e.exception))
        with self.assertRaises(ValueError):  # folder does not exist
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "no", "such", "x.png"))
        with self.assertRaises(ValueError):  # unsupported extension
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.bmpx"))
        with self.assertRaises(ValueError):  # would overwrite the input
            cgtmo.apply_file(self.exr, self.exr)
        with self.assertRaises(ValueError):
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.png"), op="drago", params={"b": 2})
        with self.assertRaises(cgtmo.DataError):
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "x.png"), layer="NoSuchLayer")
        notexr = os.path.join(self.dir, "garbage.exr")
        with open(notexr, "wb") as f:
            f.write(b"not an image at all")
        with self.assertRaises(cgtmo.DataError):
            cgtmo.apply_file(notexr, os.path.join(self.dir, "x.png"))
        self.assertEqual(sorted(os.listdir(self.dir)), sorted(before + ["garbage.exr"]))


def write_scene(path, beauty, depth=5.0):
    """A Blender-style multilayer EXR: Combined, Depth, Normal, Position, DiffCol (one light group)."""
    h, w, _ = beauty.shape
    ys, xs = np.mgrid[0:h, 0:w].astype(np.float32)
    planes = [beauty[..., 0], beauty[..., 1], beauty[..., 2], np.ones((h, w), np.float32),
              np.full((h, w), depth, np.float32),
              np.zeros((h, w), np.float32), np.zeros((h, w), np.float32), np.ones((h, w), np.float32),
              xs * 0.01, ys * 0.01, np.zeros((h, w), np.float32),
              np.full((h, w), 0.5, np.float32), np.full((h, w), 0.5, np.float32), np.full((h, w), 0.5, np.float32),
              beauty[..., 0], beauty[..., 1], beauty[..., 2]]
    names = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A",
             "ViewLayer.Depth.Z", "ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z",
             "ViewLayer.Position.X", "ViewLayer.Position.Y", "ViewLayer.Position.Z",
             "ViewLayer.DiffCol.R", "ViewLayer.DiffCol.G", "ViewLayer.DiffCol.B",
             "ViewLayer.Combined_key.R", "ViewLayer.Combined_key.G", "ViewLayer.Combined_key.B"]
    write_exr(path, np.stack(planes, axis=2).astype(np.float32), names)


COMMITTED_SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "cornell", "cornell.exr")


@unittest.skipUnless(hasattr(cgtmo, "apply_scene"), "the library has no scene operators")
class SceneOperators(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_listed_with_parameters(self):
        ops = {o["name"]: o for o in cgtmo.operators() if o["scope"] == "scene"}
        self.assertEqual(set(ops), {"cgtmo", "wls"})
        self.assertIn("b", [p["name"] for p in ops["cgtmo"]["params"]])
        # A scene operator has no per-pixel form: apply() refuses it with a ValueError naming it.
        with self.assertRaisesRegex(ValueError, "'cgtmo' is a scene operator"):
            cgtmo.apply(test_image(), op="cgtmo")

    def test_needs(self):
        self.assertTrue(cgtmo.scene_needs("cgtmo")["gbuffer"])
        self.assertFalse(cgtmo.scene_needs("cgtmo", {"filter": "bilateral"})["gbuffer"])
        with self.assertRaises(ValueError):
            cgtmo.scene_needs("drago")
        with self.assertRaises(ValueError):
            cgtmo.scene_needs("cgtmo", {"filter": "nonsense"})

    def test_flat_frame_is_global_drago(self):
        # On a frame of one colour the base layer is the luminance itself, so Ld = TC(Lw): the local
        # operator must give the global Drago curve with the same Lw_max, Lw_a and bias.
        beauty = np.empty((40, 60, 3), np.float32)
        beauty[:] = [2.0, 1.5, 0.5]
        exr = os.path.join(self.dir, "flat.exr")
        write_scene(exr, beauty)
        params = {"lw_max": 40.0, "lw_a": 0.5, "b": 0.8}
        for filt in ("exact", "fast", "bilateral"):
            with self.subTest(filter=filt):
                out = os.path.join(self.dir, "flat_%s.exr" % filt)
                rep = cgtmo.apply_scene(exr, out, op="cgtmo", params=dict(params, filter=filt), encode=False)
                local = read_image(out)[..., :3]
                glob = cgtmo.apply(beauty, op="drago", params=params, encode=False)
                np.testing.assert_allclose(local, glob, atol=2e-6)
                self.assertEqual(rep["params"]["filter"], filt)
                self.assertTrue(rep["explain"])

    @unittest.skipUnless(os.path.exists(COMMITTED_SCENE), "no committed cornell scene")
    def test_committed_scene_same_pixels_as_cli(self):
        for op, params in (("cgtmo", {}), ("cgtmo", {"filter": "poisson", "b": 0.8}), ("wls", {})):
            with self.subTest(op=op, params=params):
                mine, theirs = os.path.join(self.dir, "py.png"), os.path.join(self.dir, "cli.png")
                rep = cgtmo.apply_scene(COMMITTED_SCENE, mine, op=op, params=params)
                args = [CLI, "apply", COMMITTED_SCENE, "-o", theirs, "--op", op, "-q"]
                for k, v in params.items():
                    args += ["-p", "%s=%s" % (k, v)]
                p = subprocess.run(args, capture_output=True, text=True)
                self.assertEqual(p.returncode, 0, p.stderr)
                np.testing.assert_array_equal(read_image(mine), read_image(theirs))
                # probe, sidecar and passes all found (cornell's world light group is black: noted)
                self.assertFalse([n for n in rep["notes"] if "no probe" in n or "no sidecar" in n], rep["notes"])

    def test_errors_write_nothing(self):
        exr = os.path.join(self.dir, "s.exr")
        write_scene(exr, np.full((8, 8, 3), 0.3, np.float32))
        before = sorted(os.listdir(self.dir))
        with self.assertRaises(ValueError):
            cgtmo.apply_scene(exr, os.path.join(self.dir, "x.png"), op="drago")
        with self.assertRaises(ValueError):
            cgtmo.apply_scene(exr, os.path.join(self.dir, "x.png"), params={"b": 3})
        with self.assertRaises(cgtmo.DataError):
            cgtmo.apply_scene(os.path.join(self.dir, "none.exr"), os.path.join(self.dir, "x.png"))
        self.assertEqual(sorted(os.listdir(self.dir)), before)

    def test_sidecar_that_is_not_an_object_is_bad_data(self):
        # As in every face: JSON that is no object is not another tool's document (it was ignored).
        exr = os.path.join(self.dir, "s.exr")
        write_scene(exr, np.full((8, 8, 3), 0.3, np.float32))
        for text, kind in (("[1, 2]", "an array"), ("null", "null"), ("42", "a number"), ('"text"', "a string")):
            with self.subTest(kind=kind):
                with open(os.path.join(self.dir, "s.json"), "w") as f:
                    f.write(text)
                with self.assertRaisesRegex(cgtmo.DataError, r"^sidecar '.*s\.json': not a JSON object \(%s\)$" % kind):
                    cgtmo.apply_scene(exr, os.path.join(self.dir, "x.png"))
                self.assertFalse(os.path.exists(os.path.join(self.dir, "x.png")))


class DisplayWindow(unittest.TestCase):
    def test_held_to_the_memory_budget_with_the_work(self):
        # A 96x54 data window in a 3,932,256x54 display window (a file of a few hundred bytes) read
        # by the same library calls as the CLI: refused from the header, naming the window, before
        # anything is allocated by it (before: 7.6 GB for apply_file to EXR, past 18 GB for
        # apply_scene). The budget is half of Slurm's memory request, in a process of its own.
        with tempfile.TemporaryDirectory() as d:
            exr = os.path.join(d, "wide.exr")
            spec = oiio.ImageSpec(96, 54, 3, oiio.HALF)
            spec.full_width, spec.full_height = 3932256, 54
            out = oiio.ImageOutput.create(exr)
            out.open(exr, spec)
            out.write_image(np.full((54, 96, 3), 0.5, np.float32))
            out.close()
            script = """
import resource, sys, cgtmo
for call in (lambda: cgtmo.apply_file(sys.argv[1], sys.argv[2] + ".exr"),
             lambda: cgtmo.apply_scene(sys.argv[1], sys.argv[2] + ".png")):
    try:
        call()
        print("accepted")
    except cgtmo.DataError as e:
        print(e)
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024)
"""
            env = dict(os.environ, SLURM_MEM_PER_NODE="8000")  # MB: a budget of 4000 MB
            p = subprocess.run([sys.executable, "-c", script, exr, os.path.join(d, "out")], env=env,
                               capture_output=True, text=True, timeout=120)
            self.assertEqual(p.returncode, 0, p.stderr)
            lines = p.stdout.splitlines()
            window = "the display window 3932256x54 at (0,0) (data window 96x54 at (0,0)) needs 2.4 GB to read as float32"
            self.assertIn(window, lines[0])
            self.assertIn("with the work of --op drago, more than the memory budget of 4000 MB", lines[0])
            self.assertIn(window, lines[1])
            self.assertIn("with the work of --op cgtmo (filter fast), more than the memory budget of 4000 MB", lines[1])
            self.assertLess(int(lines[2]), 400, "peak MB")
            self.assertEqual(sorted(os.listdir(d)), ["wide.exr"])


class Threads(unittest.TestCase):
    def test_the_library_range_only(self):
        # One range with the CLI's --threads: 40,000 made a pool that killed the interpreter
        # (SIGSEGV) and -1 was taken silently.
        self.assertEqual(cgtmo.max_threads, 1024)
        for bad in (-1, 1025, 40000, 2 ** 40):
            with self.subTest(n=bad):
                with self.assertRaisesRegex(ValueError, r"^threads: %d is not in \[0, 1024\]" % bad):
                    cgtmo.set_threads(bad)
        for good in (0, 3, 1024):
            cgtmo.set_threads(good)
        cgtmo.set_threads(0)


class RequestChecks(unittest.TestCase):
    """Exposure and display choice are checked once, in the library: both pipelines refuse the same
    requests with the same message, before anything is written."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.exr = os.path.join(self.dir, "s.exr")
        write_scene(self.exr, np.full((8, 8, 3), 0.3, np.float32))

    def tearDown(self):
        self.tmp.cleanup()

    def refused(self, message, **kw):
        img = np.full((4, 4, 3), 0.3, np.float32)
        before = sorted(os.listdir(self.dir))
        with self.assertRaises(ValueError) as e:
            cgtmo.apply(img, op="drago", **kw)
        self.assertEqual(str(e.exception), message)
        with self.assertRaises(ValueError) as e:
            cgtmo.apply_file(self.exr, os.path.join(self.dir, "g.png"), op="drago", **kw)
        self.assertEqual(str(e.exception), message)
        with self.assertRaises(ValueError) as e:
            cgtmo.apply_scene(self.exr, os.path.join(self.dir, "s.png"), op="cgtmo", **kw)
        self.assertEqual(str(e.exception), message)
        self.assertEqual(sorted(os.listdir(self.dir)), before)

    def test_exposure_range(self):
        self.assertEqual(cgtmo.max_exposure_stops, 64)
        for ev in (64.5, -65.0, float("nan"), float("inf")):
            with self.subTest(exposure=ev):
                self.refused("exposure must be within [-64, 64] stops", exposure=ev)

    def test_display_or_view_without_encoding(self):
        message = "a display or view cannot be combined with linear (unencoded) output"
        self.refused(message, encode=False, display="sRGB")
        self.refused(message, encode=False, view="Standard")

    def test_exposure_range_ends_accepted(self):
        img = np.full((4, 4, 3), 0.3, np.float32)
        for ev in (-64.0, 64.0):
            self.assertTrue(np.isfinite(cgtmo.apply(img, op="reinhard", exposure=ev)).all())


class Version(unittest.TestCase):
    def test_module_and_cli_report_one_version(self):
        """The module's __version__ is the library's, as `cgtmo --version` prints it (the CMake
        project version)."""
        line = subprocess.run([CLI, "--version"], check=True, capture_output=True, text=True).stdout
        self.assertEqual(line.split()[:2], ["cgtmo", cgtmo.__version__])
        self.assertRegex(cgtmo.__version__, r"^[0-9]+\.[0-9]+\.[0-9]+$")


SHIPPED_CONFIG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ocio_config", "config.ocio")


@unittest.skipUnless(hasattr(cgtmo, "bake"), "the library has no LUT baker")
class InputColorSpace(unittest.TestCase):
    """colorspace= and the chromaticities attribute, through the same library call as the CLI."""
    # ACEScg (AP1, D60) -> linear Rec.709 (D65), Bradford, as published with the ACES configs.
    AP1_TO_REC709 = np.array([[1.7050509927, -0.6217921206, -0.0832588720],
                              [-0.1302564175, 1.1408047366, -0.0105483190],
                              [-0.0240033568, -0.1289689761, 1.1529723329]])

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.img = test_image(24, 40)
        self.ap1 = np.ascontiguousarray((self.img @ np.linalg.inv(self.AP1_TO_REC709).T).astype(np.float32))
        self.rec709_exr = os.path.join(self.dir, "rec709.exr")
        write_exr(self.rec709_exr, self.img)
        self.ap1_exr = os.path.join(self.dir, "acescg.exr")
        spec = oiio.ImageSpec(40, 24, 3, oiio.FLOAT)
        spec.attribute("chromaticities", oiio.TypeDesc("float[8]"),
                       (0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767))
        out = oiio.ImageOutput.create(self.ap1_exr)
        out.open(self.ap1_exr, spec)
        out.write_image(self.ap1)
        out.close()

    def tearDown(self):
        self.tmp.cleanup()

    def test_attribute_read_like_the_cli(self):
        mine, theirs, ref = (os.path.join(self.dir, n) for n in ("py.png", "cli.png", "ref.png"))
        rep = cgtmo.apply_file(self.ap1_exr, mine, op="agx")
        self.assertIn("ACEScg (AP1) primaries", rep["colorspace"])
        p = subprocess.run([CLI, "apply", self.ap1_exr, "-o", theirs, "--op", "agx", "-q"], capture_output=True,
                           text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        np.testing.assert_array_equal(read_image(mine), read_image(theirs))
        cgtmo.apply_file(self.rec709_exr, ref, op="agx")
        diff = np.abs(read_image(mine).astype(int) - read_image(ref).astype(int)).max()
        self.assertLessEqual(diff, 1)

    def test_named_space_on_arrays(self):
        config = SHIPPED_CONFIG
        if not os.path.exists(config):
            self.skipTest("no shipped config")
        a, rep = cgtmo.apply(self.ap1, op="reinhard", config=config, colorspace="ACEScg", report=True)
        self.assertEqual(rep["colorspace"], "OCIO colour space 'ACEScg'")
        b = cgtmo.apply(self.img, op="reinhard", config=config)
        self.assertLess(np.abs(a - b).max() * 255, 1.0)
        wrong = cgtmo.apply(self.ap1, op="reinhard", config=config)
        self.assertGreater(np.abs(wrong - b).max() * 255, 4.0)

    def test_unknown_name(self):
        with self.assertRaises(ValueError) as e:  # UsageError
            cgtmo.apply(self.img, colorspace="Nope")
        self.assertIn("'Nope'", str(e.exception))
        with self.assertRaises(ValueError):
            cgtmo.apply_scene(COMMITTED_SCENE, os.path.join(self.dir, "x.png"), colorspace="Nope")
        self.assertFalse(os.path.exists(os.path.join(self.dir, "x.png")))


class Bake(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_bad_folders_write_nothing(self):
        with self.assertRaises(ValueError) as e:
            cgtmo.bake(os.path.join(self.dir, "no-luts"), self.dir)
        self.assertIn("no-luts", str(e.exception))
        exr = os.path.join(self.dir, "r.exr")
        write_exr(exr, test_image(16, 16, seed=3))
        with self.assertRaises(ValueError):  # a LUT folder that does not exist
            cgtmo.bake_scene(exr, luts_dir=os.path.join(self.dir, "no-luts"), config_dir=self.dir)
        self.assertEqual(os.listdir(self.dir), ["r.exr"])

    def test_scene_into_a_fresh_folder(self):
        # No config.ocio there yet: the copy starts from the built-in displays.
        exr = os.path.join(self.dir, "r.exr")
        write_exr(exr, test_image(16, 16, seed=3))
        cgtmo.bake_scene(exr, luts_dir=self.dir, config_dir=self.dir)
        self.assertIn("r.ocio", os.listdir(self.dir))
        self.assertTrue([f for f in os.listdir(self.dir) if f.startswith("drago-r.")])

    @unittest.skipUnless(os.path.exists(SHIPPED_CONFIG), "no shipped ocio_config/config.ocio to copy")
    def test_scene_look_same_as_cli(self):
        import shutil
        exr = os.path.join(self.dir, "shot.exr")
        write_exr(exr, test_image(32, 48, seed=7))
        dirs = {}
        for who in ("py", "cli"):
            luts, cfg = os.path.join(self.dir, who, "luts"), os.path.join(self.dir, who, "cfg")
            os.makedirs(luts)
            os.makedirs(cfg)
            shutil.copyfile(SHIPPED_CONFIG, os.path.join(cfg, "config.ocio"))
            dirs[who] = (luts, cfg)
        lines = []
        rep = cgtmo.bake_scene(exr, name="shot", luts_dir=dirs["py"][0], config_dir=dirs["py"][1],
                               progress=lines.append)
        p = subprocess.run([CLI, "bake", "--scene", exr, "--name", "shot", "--out-luts", dirs["cli"][0],
                            "--out-config", dirs["cli"][1], "-q"], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(rep["look"], "drago-shot")
        self.assertTrue(os.path.exists(rep["config"]))
        lut = os.path.basename(rep["lut"])

        def data(path):  # the LUT without its comment lines (they name the command that wrote it)
            with open(path) as f:
                return [l for l in f if not l.startswith("#")]
        self.assertEqual(data(rep["lut"]), data(os.path.join(dirs["cli"][0], lut)))
        img = test_image(32, 48, seed=7).astype(np.float64)
        lum = 0.2126 * img[..., 0] + 0.7152 * img[..., 1] + 0.0722 * img[..., 2]
        self.assertAlmostEqual(rep["stats"]["max_luminance"], lum.max(), delta=1e-5 * lum.max())
        self.assertTrue(lines, "progress lines reach the callback")


class ColorConfig(unittest.TestCase):
    def test_builtin_config(self):
        env = dict(os.environ)
        env.pop("OCIO", None)
        code = "import cgtmo, json; print(json.dumps(cgtmo.color_config()))"
        cfg = json.loads(subprocess.run([sys.executable, "-c", code], env=env, check=True, capture_output=True,
                                        text=True).stdout)
        self.assertEqual(cfg["origin"], "built-in config")
        for d in ("sRGB", "Rec.1886", "Display P3"):
            self.assertIn(d, cfg["displays"])
            self.assertIn("Standard", cfg["displays"][d])

    def test_missing_config_file(self):
        with self.assertRaises(ValueError) as e:
            cgtmo.color_config("/no/such/config.ocio")
        self.assertIn("/no/such/config.ocio", str(e.exception))


class Tmqi(unittest.TestCase):
    def test_combination_follows_published_constants(self):
        hdr = test_image(180, 200, seed=3)
        ldr = cgtmo.apply(hdr, op="reinhard") * 255.0
        r = cgtmo.tmqi(hdr, ldr)
        a, alpha, beta = 0.8012, 0.3046, 0.7088
        self.assertAlmostEqual(r["Q"], a * r["S"] ** alpha + (1 - a) * r["N"] ** beta, places=12)
        weights = (0.0448, 0.2856, 0.3001, 0.2363, 0.1333)
        self.assertAlmostEqual(r["S"], math.prod(s ** w for s, w in zip(r["S_local"], weights)), places=12)
        for k in ("Q", "S", "N"):
            self.assertTrue(0.0 <= r[k] <= 1.0, (k, r[k]))

    @unittest.skipUnless(hasattr(cgtmo, "evaluate_scene"), "the library has no scene evaluation")
    def test_evaluate_scene_global_drago(self):
        # The 'drago' column is the global registry operator, sRGB-encoded and quantised to 8 bits:
        # recomputed here from apply() and tmqi(), it must give the same Q.
        with tempfile.TemporaryDirectory() as d:
            hdr = test_image(170, 180, seed=5)
            exr = os.path.join(d, "scene.exr")
            write_scene(exr, hdr)
            r = cgtmo.evaluate_scene(exr)
            self.assertEqual((r["width"], r["height"]), (180, 170))
            for method in ("drago", "cgtmo-exact", "cgtmo-fast", "wls"):
                self.assertIn(method, r["scores"])
            ldr = np.round(cgtmo.apply(hdr, op="drago") * 255.0)
            mine = cgtmo.tmqi(hdr, ldr)
            self.assertAlmostEqual(r["scores"]["drago"]["Q"], mine["Q"], places=9)

    def test_uint8_ldr_accepted_and_sizes_checked(self):
        hdr = test_image(170, 170, seed=4)
        ldr8 = np.round(cgtmo.apply(hdr, op="hable") * 255.0).astype(np.uint8)
        r8 = cgtmo.tmqi(hdr, ldr8)
        rf = cgtmo.tmqi(hdr, ldr8.astype(np.float32))
        self.assertEqual(r8, rf)
        with self.assertRaises(ValueError):
            cgtmo.tmqi(hdr, ldr8[:100])
        with self.assertRaises(cgtmo.DataError):  # below the 161-pixel minimum of 5 scales
            cgtmo.tmqi(hdr[:100, :100], ldr8[:100, :100])


if __name__ == "__main__":
    if "--cgtmo" in sys.argv:
        i = sys.argv.index("--cgtmo")
        CLI = sys.argv[i + 1]
        del sys.argv[i:i + 2]
    if not CLI or not os.path.exists(CLI):
        sys.exit("usage: test_module.py --cgtmo PATH_TO_CGTMO [unittest args]")
    unittest.main(verbosity=2)
