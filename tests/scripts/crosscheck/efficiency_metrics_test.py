"""Unit tests of scripts/crosscheck/efficiency*.py on synthetic images (no renderer runs):
relMSE and efficiency against exact values and against the 1/spp law of an unbiased
estimator, the reference-error correction, reading images back exactly, Cycles' status
lines, and the many-lights-hall scene's materials (scripts/make_many_lights.py has
tests/scripts/make_many_lights_test.py). Run by
tests/scripts/efficiency_test.cpp:  python3 -m unittest efficiency_metrics_test
"""
import array
import json
import os
import random
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path[:0] = [os.path.join(ROOT, "scripts", "crosscheck"), os.path.join(ROOT, "scripts")]

from efficiency_metrics import (EPSILON, average, efficiency, median, read_rgb,  # noqa: E402
                                reference_relmse, relmse, write_pfm)
from efficiency_render import (Cache, CyclesSession, cycles_path_tracing_seconds,  # noqa: E402
                               interleave, status_seconds)
from efficiency_scenes import ALL, QUICK, SCENES, prepare  # noqa: E402
from error_regions import block_table, pixel_relmse  # noqa: E402

PIXELS = 3 * 4096


def exact_image(rng):
    """Radiances spread over 0.05 .. 5, so EPSILON matters for some pixels and not others."""
    return array.array("f", [0.05 * 100 ** rng.random() for _ in range(PIXELS)])


def render(exact, spp, rng, sigma=1.0):
    """An unbiased 'renderer': each sample is the exact value times (1 + sigma g), g standard
    normal; the pixel is the mean of spp samples, so its variance is (sigma x)^2 / spp."""
    return array.array("f", [x * (1 + sigma * rng.gauss(0, 1) / spp ** 0.5) for x in exact])


def expected_relmse(exact, spp, sigma=1.0):
    return sum((sigma * x) ** 2 / spp / (x * x + EPSILON) for x in exact) / len(exact)


class RelMse(unittest.TestCase):
    def test_exact_value_of_a_known_offset(self):
        ref = [0.0, 0.1, 1.0, 10.0]
        image = [0.2, 0.1, 1.5, 9.0]
        want = (0.04 / EPSILON + 0 + 0.25 / (1 + EPSILON) + 1 / (100 + EPSILON)) / 4
        self.assertAlmostEqual(relmse(image, ref), want, places=12)
        self.assertEqual(relmse(ref, ref), 0.0)

    def test_sizes_must_agree(self):
        with self.assertRaises(ValueError):
            relmse([1.0, 2.0], [1.0])

    def test_unbiased_estimator_matches_its_variance_and_falls_as_one_over_spp(self):
        # 12288 values: one relMSE estimate has a relative standard deviation of about
        # sqrt(2 / 12288) = 1.3%, so 5% bounds hold at about 4 sigma and a renderer whose
        # error fell as 1 / spp^0.9 (16 -> 64: 3.5x instead of 4x) fails the ratio check.
        rng = random.Random(7)
        exact = exact_image(rng)
        r16 = relmse(render(exact, 16, rng), exact)
        r64 = relmse(render(exact, 64, rng), exact)
        self.assertAlmostEqual(r16 / expected_relmse(exact, 16), 1.0, delta=0.05)
        self.assertAlmostEqual(r64 / expected_relmse(exact, 64), 1.0, delta=0.05)
        self.assertAlmostEqual(r16 / r64, 4.0, delta=0.3)


class Efficiency(unittest.TestCase):
    def test_definition(self):
        self.assertAlmostEqual(efficiency(0.01, 2.0), 50.0)
        self.assertEqual(efficiency(0.0, 1.0), float("inf"))
        with self.assertRaises(ValueError):
            efficiency(0.1, 0.0)

    def test_independent_of_spp_and_ratio_of_two_renderers(self):
        # Renderer A: 1 s per 64 spp; B: half the time per sample but twice the variance
        # (sigma sqrt(2)), so B's efficiency is A's within the noise; C: A's variance at twice
        # A's time, half A's efficiency.
        rng = random.Random(11)
        exact = exact_image(rng)
        eff = {}
        for spp in (16, 64):
            eff["A", spp] = efficiency(relmse(render(exact, spp, rng), exact), spp / 64)
            eff["B", spp] = efficiency(relmse(render(exact, spp, rng, 2 ** 0.5), exact),
                                       spp / 128)
            eff["C", spp] = efficiency(relmse(render(exact, spp, rng), exact), spp / 32)
        self.assertAlmostEqual(eff["A", 16] / eff["A", 64], 1.0, delta=0.07)
        self.assertAlmostEqual(eff["B", 64] / eff["A", 64], 1.0, delta=0.07)
        self.assertAlmostEqual(eff["C", 64] / eff["A", 64], 0.5, delta=0.035)

    def test_median(self):
        self.assertEqual(median([3.0, 1.0, 2.0]), 2.0)
        self.assertEqual(median([4.0, 1.0, 2.0, 3.0]), 2.5)


class ReferenceError(unittest.TestCase):
    def test_estimate_from_two_halves_and_its_correction(self):
        # A reference of two 256-spp halves measured against the exact image, and a 16-spp
        # image measured against the reference: measured - reference estimate = the true
        # relMSE against the exact image (within the estimates' noise, 5%).
        rng = random.Random(3)
        exact = exact_image(rng)
        a, b = render(exact, 256, rng), render(exact, 256, rng)
        ref = average(a, b)
        self.assertAlmostEqual(reference_relmse(a, b) / relmse(ref, exact), 1.0, delta=0.05)
        self.assertAlmostEqual(reference_relmse(a, b) / expected_relmse(exact, 512), 1.0,
                               delta=0.05)
        image = render(exact, 16, rng)
        corrected = relmse(image, ref) - reference_relmse(a, b)
        self.assertAlmostEqual(corrected / relmse(image, exact), 1.0, delta=0.05)
        # Without the correction the error is overstated by the reference's share: 1/32.
        self.assertGreater(relmse(image, ref) / relmse(image, exact), 1.02)


class Images(unittest.TestCase):
    def test_exr_values_come_back_exactly(self):
        rng = random.Random(5)
        w, h = 5, 3  # not square: rows and columns must not be swapped
        rgb = array.array("f", [rng.uniform(0, 50) for _ in range(3 * w * h)])
        with tempfile.TemporaryDirectory() as tmp:
            pfm, exr = os.path.join(tmp, "a.pfm"), os.path.join(tmp, "a.exr")
            write_pfm(pfm, w, h, rgb)
            subprocess.run(["oiiotool", pfm, "-d", "float", "-o", exr], check=True,
                           capture_output=True)
            width, height, back = read_rgb(exr)
        self.assertEqual((width, height), (w, h))
        self.assertEqual(list(back), list(rgb))


class CyclesLog(unittest.TestCase):
    LOG = """Fra:1 Mem:9.60M | Time:00:00.00 | Mem:0.00M | Scene, ViewLayer | Synchronizing object | Cube
Fra:1 Mem:9.85M | Time:00:00.31 | Mem:0.00M | Scene, ViewLayer | Updating Scene BVH
Fra:1 Mem:10.21M | Time:00:00.40 | Mem:0.76M | Scene, ViewLayer | Sample 0/64
Fra:1 Mem:10.36M | Time:00:00.50 | Remaining:00:00.05 | Mem:0.90M | Scene, ViewLayer | Sample 1/64
Fra:1 Mem:10.42M | Time:00:02.37 | Mem:0.90M | Scene, ViewLayer | Sample 64/64
Fra:1 Mem:10.42M | Time:00:02.37 | Mem:0.90M | Scene, ViewLayer | Finished
Saved: 'x.exr'
Fra:1 Mem:10.21M | Time:00:00.00 | Mem:0.76M | Scene, ViewLayer | Sample 0/256
Fra:1 Mem:10.42M | Time:01:02:03.25 | Mem:0.90M | Scene, ViewLayer | Sample 256/256
Fra:1 Mem:10.42M | Time:01:02:03.25 | Mem:0.90M | Scene, ViewLayer | Finished
"""

    def test_path_tracing_time_per_render_without_sync(self):
        self.assertEqual(status_seconds("| Time:01:02.50 |"), 62.5)
        self.assertIsNone(status_seconds("no time here"))
        times = cycles_path_tracing_seconds(self.LOG)
        self.assertEqual(len(times), 2)
        self.assertAlmostEqual(times[0], 1.97)
        self.assertAlmostEqual(times[1], 3723.25)


class Retime(unittest.TestCase):
    def test_timed_renders_from_before_the_run_are_rendered_again_references_kept(self):
        with tempfile.TemporaryDirectory() as root:
            cache = Cache(root, "s", {"hash": "h"}, {"key": "k"}, {"spp": 1})
            for spp in (16, 512):
                open(cache.path(spp, 1), "w").close()
                json.dump({"seconds": 1.0, "cpu_s": 2.0}, open(cache.path(spp, 1) + ".json", "w"))
            old = os.path.getmtime(cache.path(16, 1) + ".json")
            try:
                self.assertTrue(cache.done(16, 1))
                Cache.retime_since = old + 1
                self.assertFalse(cache.done(16, 1))                 # timed: render again
                self.assertTrue(cache.done(512, 1, need_cpu=False))  # a reference: kept
                os.utime(cache.path(16, 1) + ".json", (old + 2, old + 2))
                self.assertTrue(cache.done(16, 1))                  # rendered in this run
            finally:
                Cache.retime_since = None


# A stand-in for Blender running efficiency_cycles.py with a paced job: the same protocol
# and output lines, each render a line in the shared log (argv[1]) and a stand-in image.
FAKE_BLENDER = r"""
import json, sys, time
log, job = sys.argv[1], json.load(open(sys.argv[2]))
def line(text):
    print(text)
    sys.stdout.flush()
time.sleep(0.2)  # start-up: launch, import, sync
open(log, "a").write("cycles started\n")
walls = []
for i, r in enumerate([{"spp": 1, "seed": 0, "out": None}] + job["renders"]):
    if i and job.get("paced"):
        line("EFFICIENCY-READY")
        if sys.stdin.readline().strip() != "go":
            line("EFFICIENCY-ERROR stopped")
            sys.exit(2)
    line("Fra:1 | Time:00:0%d.00 | Mem:1M | Scene | Sample 0/%d" % (i, r["spp"]))
    line("Fra:1 | Time:00:0%d.50 | Mem:1M | Scene | Sample %d/%d" % (i, r["spp"], r["spp"]))
    line("Fra:1 | Time:00:0%d.50 | Mem:1M | Scene | Finished" % i)
    if r["out"]:
        open(log, "a").write("cycles %d %d\n" % (r["spp"], r["seed"]))
        open(r["out"], "w").write("image")
        walls.append(0.05)
        if job.get("paced"):
            line("EFFICIENCY-RENDERED")
line("EFFICIENCY " + json.dumps({"setup_s": 0.1, "render_wall_s": walls,
     "render_cpu_s": [1.0] * len(walls), "cpu_1spp_s": 0.2, "sampling_pattern": "FAKE",
     "version": "fake"}))
time.sleep(0.2)  # exit
open(log, "a").write("cycles exited\n")
"""


class Interleave(unittest.TestCase):
    def test_order_alternates_which_renderer_goes_first_and_keeps_single_renders(self):
        p = [(512, 1001), (16, 1), (16, 2), (64, 1)]
        c = [(16, 1), (16, 2), (64, 1), (64, 2)]
        self.assertEqual(interleave(p, c), [
            ("penumbra", (512, 1001)),
            ("penumbra", (16, 1)), ("cycles", (16, 1)),
            ("cycles", (16, 2)), ("penumbra", (16, 2)),
            ("penumbra", (64, 1)), ("cycles", (64, 1)),
            ("cycles", (64, 2))])
        self.assertEqual(interleave([], c), [("cycles", k) for k in c])

    def test_paced_session_renders_each_one_when_told_and_files_its_times(self):
        class Args:
            max_depth, threads, timeout = 8, 2, 60
        with tempfile.TemporaryDirectory() as root:
            cache = Cache(root, "cornell", {"hash": "h"}, {"key": "fake"}, {"spp": 1})
            camera = os.path.join(root, "camera.exr")
            header = {"worldToCamera": " ".join(["1"] * 16), "worldToNDC": " ".join(["1"] * 16)}
            write_pfm(os.path.join(root, "c.pfm"), 4, 2, [0.5] * 24)
            subprocess.run(["oiiotool", os.path.join(root, "c.pfm")] +
                           sum([["--attrib:type=matrix", k, v] for k, v in header.items()], []) +
                           ["-o", camera], check=True, capture_output=True)
            log = os.path.join(root, "log")
            fake = os.path.join(root, "fake_blender.py")
            open(fake, "w").write(FAKE_BLENDER)
            todo = [(16, 1), (16, 2)]
            session = CyclesSession(Args, "cornell", {"scene": "s.gltf", "env": None}, cache,
                                    camera, todo, paced=True,
                                    command=[sys.executable, fake, log])
            for spp, seed in todo:
                open(log, "a").write("penumbra %d %d\n" % (spp, seed))
                time.sleep(0.5)  # penumbra's render: not Cycles' process time
                session.render_next()
            open(log, "a").write("driver\n")
            time.sleep(1.0)  # the driver's work after Blender's last render
            session.finish()
            # Blender's start-up and exit never overlap a render of penumbra's or the
            # driver's work after the last render (they slowed penumbra's renders).
            self.assertEqual(open(log).read().split("\n"),
                             ["cycles started", "penumbra 16 1", "cycles 16 1", "penumbra 16 2",
                              "cycles 16 2", "cycles exited", "driver", ""])
            job = json.load(open(os.path.join(cache.dir, "job.json")))
            self.assertTrue(job["paced"])
            self.assertEqual((job["width"], job["height"]), (4, 2))
            for spp, seed in todo:
                self.assertTrue(cache.done(spp, seed))
                times = cache.times(spp, seed)
                self.assertAlmostEqual(times["render_s"], 0.5)
                self.assertEqual(times["cpu_s"], 1.0)
                # The stand-in's reported 0.05 s plus its share of a start-up well under
                # a second; the pauses (0.5 s, then 1 s) would add 0.75 s each.
                self.assertLess(times["process_s"], 0.05 + 0.4)


class HallScene(unittest.TestCase):
    def test_the_generators_hall_with_lambertian_receivers_and_exact_materials(self):
        self.assertEqual(SCENES["many-lights-hall"]["materials"], "exact")
        self.assertIn("many-lights-hall", ALL)
        self.assertNotIn("many-lights-hall", QUICK)
        with tempfile.TemporaryDirectory() as tmp:
            made = prepare("many-lights-hall", tmp)
            raw = os.path.join(tmp, "raw.gltf")
            subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_many_lights.py"),
                            raw, "--layout", "hall"], check=True)
            with open(made["scene"]) as f, open(raw) as g:
                doc, want = json.load(f), json.load(g)
            self.assertEqual(made["hash"], prepare("many-lights-hall", tmp)["hash"])
        # Only the receivers change: each gets KHR_materials_specular factor 0 (what Cycles'
        # exact rebuild needs for a Diffuse BSDF); emitters and geometry stay as generated.
        receivers = 0
        for m in want["materials"]:
            if max(m.get("emissiveFactor", [0, 0, 0])) == 0:
                self.assertEqual(m["pbrMetallicRoughness"]["metallicFactor"], 0)
                m.setdefault("extensions", {})["KHR_materials_specular"] = {
                    "specularFactor": 0.0}
                receivers += 1
        self.assertEqual(receivers, 1)
        want["extensionsUsed"].append("KHR_materials_specular")
        self.assertEqual(doc, want)


if __name__ == "__main__":
    unittest.main()


class ErrorRegionsTest(unittest.TestCase):
    """scripts/crosscheck/error_regions.py's per-pixel relMSE and block table."""

    def test_pixel_relmse_is_the_mean_over_images_and_channels(self):
        ref = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]  # two pixels
        a = [1.1, 1.0, 1.0, 0.1, 0.1, 0.1]
        b = [1.0, 1.0, 0.7, 0.0, 0.0, 0.0]
        got = pixel_relmse([a, b], ref, eps=0.01)
        want0 = (0.01 / 1.01 / 3 + 0.09 / 1.01 / 3) / 2
        want1 = (3 * 0.01 / 0.01 / 3 + 0) / 2
        self.assertAlmostEqual(got[0], want0, places=12)
        self.assertAlmostEqual(got[1], want1, places=12)

    def test_block_table_ratios_and_shares(self):
        # 3 x 2 pixels in blocks of 2: a left block of 2 x 2 and a right one of 1 x 2.
        a = [1.0, 2.0, 4.0,
             3.0, 0.0, 0.0]
        b = [1.0, 1.0, 0.0,
             1.0, 1.0, 0.0]
        table = block_table(a, b, 3, 2, 2)
        self.assertEqual(len(table), 1)
        (ratio_l, share_a_l, share_b_l), (ratio_r, share_a_r, share_b_r) = table[0]
        self.assertAlmostEqual(ratio_l, 6.0 / 4.0)
        self.assertIsNone(ratio_r)  # Cycles' block is 0
        self.assertAlmostEqual(share_a_l, 0.6)
        self.assertAlmostEqual(share_a_r, 0.4)
        self.assertAlmostEqual(share_b_l, 1.0)
        self.assertAlmostEqual(share_b_r, 0.0)
