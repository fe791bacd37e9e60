#!/usr/bin/env python3
"""Host safety: loading the `cgtmo` module into a host (Blender, Nuke, a Python session) and running
it must leave OpenImageIO's process-wide "threads" attribute as the host set it. The library keeps
its own thread count (cgtmo.set_threads) and passes it per call.

Run in a process of its own: it reads and sets OpenImageIO's global state.
Usage: test_host_threads.py --scene tests/scenes/cornell/cornell.exr"""
import argparse
import os
import sys
import tempfile
import unittest

import numpy as np
import OpenImageIO as oiio

SCENE = None
HOST_THREADS = 5  # neither 0, 1, this machine's core count nor the counts below (on 2-32 cores)


class HostThreadsUnchanged(unittest.TestCase):
    def setUp(self):
        # The same libOpenImageIO as the module's, or the check below would see another copy.
        oiio.attribute("threads", HOST_THREADS)
        self.assertEqual(oiio.get_int_attribute("threads"), HOST_THREADS)

    def assert_host_threads(self, what):
        self.assertEqual(oiio.get_int_attribute("threads"), HOST_THREADS,
                         "%s changed OpenImageIO's process-wide \"threads\" attribute" % what)

    def test_import_and_default_threads(self):
        import cgtmo
        self.assert_host_threads("import cgtmo")
        img = np.random.default_rng(1).uniform(0, 4, (64, 48, 3)).astype(np.float32)
        cgtmo.apply(img, op="reinhard")
        self.assert_host_threads("cgtmo.apply with the default thread count")

    def test_set_threads_then_apply(self):
        import cgtmo
        for n in (2, 3, 1, 0):
            cgtmo.set_threads(n)
            self.assert_host_threads("cgtmo.set_threads(%d)" % n)
        cgtmo.set_threads(3)
        img = np.random.default_rng(2).uniform(0, 4, (64, 48, 3)).astype(np.float32)
        cgtmo.apply(img, op="drago")
        self.assert_host_threads("cgtmo.apply with set_threads(3)")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out.png")
            cgtmo.apply_file(SCENE, out, op="aces-narkowicz")
            self.assert_host_threads("cgtmo.apply_file")
            self.assertTrue(os.path.getsize(out) > 0)
            # The scene operator: statistics and the G-buffer filter, on the library's own pool.
            cgtmo.apply_scene(SCENE, out, op="cgtmo")
            self.assert_host_threads("cgtmo.apply_scene")
        cgtmo.set_threads(0)


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", required=True)
    args, rest = ap.parse_known_args()
    SCENE = args.scene
    unittest.main(argv=[sys.argv[0]] + rest)
