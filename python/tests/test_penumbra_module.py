"""The Python module against the CLI: the same options give bitwise the CLI's EXR pixels,
for a bundled scene and a wild asset's orbit views; bad files and options raise clean
exceptions; the GIL is released while rendering. Run by ctest (PythonModule) with
PYTHONPATH=build/python, PENUMBRA_CLI set to the CLI and PENUMBRA_SHARED_DIR to the shared
assets (../shared by default)."""

import json
import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np
import OpenImageIO as oiio

import penumbra

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLI = os.environ.get("PENUMBRA_CLI", os.path.join(ROOT, "build", "bin", "penumbra"))
CORNELL = os.path.join(ROOT, "scenes", "cornell-box.gltf")
SHARED = os.environ.get("PENUMBRA_SHARED_DIR", os.path.join(ROOT, "..", "shared"))
FOX = os.path.join(SHARED, "scenes", "wild", "Fox", "Fox.glb")
BROKEN = os.path.join(ROOT, "scenes", "invalid", "bad-material-index.gltf")

# The EXR channels of each array the module returns for these AOVs.
CHANNELS = {
    "rgba": ["R", "G", "B", "A"],
    "albedo": ["Albedo.R", "Albedo.G", "Albedo.B"],
    "normal": ["Normal.X", "Normal.Y", "Normal.Z"],
    "depth": ["Depth.Z"],
    "noisy": ["Noisy.R", "Noisy.G", "Noisy.B"],
    "vector": ["Vector.X", "Vector.Y", "Vector.Z", "Vector.W"],
}


def read_exr(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise RuntimeError(oiio.geterror())
    spec = inp.spec()
    pixels = inp.read_image(0, 0, 0, spec.nchannels, "float")
    inp.close()
    names = list(spec.channelnames)
    return {name: pixels[:, :, names.index(name)] for name in names}


def cli_render(scene, out, *args):
    subprocess.run([CLI, "render", scene, "-o", out, "-q", "--no-preview", *args], check=True)


class ModuleMatchesCli(unittest.TestCase):
    def assert_bitwise(self, image, exr, keys):
        for key in keys:
            array = image[key]
            for c, name in enumerate(CHANNELS[key]):
                ours = array[:, :, c] if array.ndim == 3 else array
                self.assertEqual(ours.dtype, np.float32)
                # Bit patterns, so that a NaN or a -0 would count as a difference too.
                self.assertTrue(np.array_equal(ours.view(np.uint32), exr[name].view(np.uint32)),
                                f"{key} {name}: max difference "
                                f"{np.max(np.abs(ours - exr[name]))}")

    def test_bundled_scene_equals_the_cli_exr(self):
        options = dict(width=48, height=36, spp=4, aov="albedo,normal,depth")
        scene = penumbra.load(CORNELL, **options)
        image = scene.render()
        self.assertEqual(image["rgba"].shape, (36, 48, 4))
        self.assertEqual(image["depth"].shape, (36, 48))
        self.assertEqual(image["spp"], 4)
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "box.exr")
            cli_render(CORNELL, out, "--width", "48", "--height", "36", "--spp", "4",
                       "--aov", "albedo,normal,depth")
            self.assert_bitwise(image, read_exr(out), ["rgba", "albedo", "normal", "depth"])
            # Render options over the loaded scene: no second load, still the CLI's pixels.
            again = scene.render(spp=2, seed=7, exposure=1.5)
            self.assertEqual(scene.loads, 1)
            cli_render(CORNELL, out, "--width", "48", "--height", "36", "--spp", "2",
                       "--seed", "7", "--exposure", "1.5", "--aov", "albedo,normal,depth",
                       "--overwrite")
            self.assert_bitwise(again, read_exr(out), ["rgba", "albedo", "normal", "depth"])
            # Denoised: the denoiser's image as the beauty, the film's as "noisy".
            denoised = scene.render(denoise=True, aov="depth")
            self.assertEqual(scene.loads, 1)
            cli_render(CORNELL, out, "--width", "48", "--height", "36", "--spp", "4",
                       "--denoise", "--aov", "depth", "--overwrite")
            self.assert_bitwise(denoised, read_exr(out), ["rgba", "noisy", "depth"])
            self.assertFalse(np.array_equal(denoised["rgba"][..., :3], denoised["noisy"]))

    def test_wild_asset_orbit_views_equal_the_cli_exrs(self):
        scene = penumbra.load(FOX, width=40, height=32, views="orbit:2", aov="depth,normal")
        self.assertEqual(scene.view_count(), 2)
        images = [scene.render(view=v, spp=2) for v in range(2)]
        self.assertEqual(scene.loads, 1)  # one load and one accelerator for both views
        self.assertFalse(np.array_equal(images[0]["rgba"], images[1]["rgba"]))
        with tempfile.TemporaryDirectory() as tmp:
            cli_render(FOX, os.path.join(tmp, "{view}.exr"), "--views", "orbit:2", "--width",
                       "40", "--height", "32", "--spp", "2", "--aov", "depth,normal")
            for v, image in enumerate(images):
                exr = read_exr(os.path.join(tmp, f"{v:04d}.exr"))
                self.assert_bitwise(image, exr, ["rgba", "normal", "depth"])
            # The camera the module reports is transforms.json's, which the CLI wrote.
            with open(os.path.join(tmp, "transforms.json")) as f:
                frames = json.load(f)["frames"]
            for v, image in enumerate(images):
                np.testing.assert_allclose(image["camera"]["transform_matrix"],
                                           frames[v]["transform_matrix"], rtol=0, atol=1e-6)

    def test_motion_vectors_equal_the_cli_exr(self):
        scene = penumbra.load(FOX, width=40, height=32, spp=2, time=0.5, aov="depth")
        scene.render()
        # Vectors need the frames around this one: one more load, then none.
        image = scene.render(aov="vector")
        again = scene.render(aov="vector,depth")
        self.assertEqual(scene.loads, 2)
        self.assertEqual(image["vector"].shape, (32, 40, 4))
        self.assertGreater(np.abs(image["vector"]).max(), 0.01)  # the fox moves
        self.assertTrue(np.array_equal(image["vector"], again["vector"]))
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "fox.exr")
            cli_render(FOX, out, "--width", "40", "--height", "32", "--spp", "2", "--time",
                       "0.5", "--aov", "vector")
            self.assert_bitwise(image, read_exr(out), ["rgba", "vector"])

    def test_a_cameras_file_gives_the_cli_views(self):
        cameras = [{"name": "high", "position": [0.5, 1.5, 3.5], "look_at": [0, 1, 0], "yfov": 50},
                   {"matrix": [[1, 0, 0, 0.2], [0, 1, 0, 1], [0, 0, 1, 3.9], [0, 0, 0, 1]]}]
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "cams.json")
            with open(path, "w") as f:
                json.dump(cameras, f)
            scene = penumbra.load(CORNELL, width=32, height=24, views=path, aov="depth")
            images = [scene.render(view=v, spp=2) for v in range(scene.view_count())]
            self.assertEqual(len(images), 2)
            self.assertEqual(images[0]["camera"]["name"], "high")
            cli_render(CORNELL, os.path.join(tmp, "{view}.exr"), "--views", path, "--width",
                       "32", "--height", "24", "--spp", "2", "--aov", "depth")
            for v, image in enumerate(images):
                self.assert_bitwise(image, read_exr(os.path.join(tmp, f"{v:04d}.exr")),
                                    ["rgba", "depth"])
            with open(path, "w") as f:
                json.dump([{"position": [0, 1], "look_at": [0, 0, 0]}], f)
            with self.assertRaisesRegex(penumbra.SceneError, r"cams\.json: \[0\]\.position"):
                penumbra.load(CORNELL, width=32, height=24, views=path).render(view=0, spp=1)

    def test_a_view_out_of_range_is_a_value_error(self):
        scene = penumbra.load(CORNELL, width=16, height=12, views="orbit:2")
        with self.assertRaisesRegex(ValueError, "view=2: expected 0 to 1"):
            scene.render(view=2, spp=1)
        with self.assertRaisesRegex(ValueError, "no views"):
            penumbra.load(CORNELL, width=16, height=12).render(view=0, spp=1)


class Errors(unittest.TestCase):
    def test_a_missing_or_broken_file_is_a_scene_error(self):
        self.assertTrue(issubclass(penumbra.SceneError, Exception))
        with self.assertRaisesRegex(penumbra.SceneError, "no-such-file.glb"):
            penumbra.load("no-such-file.glb")
        with self.assertRaisesRegex(penumbra.SceneError, "bad-material-index.gltf"):
            penumbra.load(BROKEN)

    def test_bad_options_are_value_errors_naming_the_option(self):
        with self.assertRaisesRegex(ValueError, "^spp: expected an integer"):
            penumbra.load(CORNELL, spp="many")
        with self.assertRaisesRegex(ValueError, "^sppp: unknown option"):
            penumbra.load(CORNELL, sppp=4)
        with self.assertRaisesRegex(ValueError, "^sampler: "):
            penumbra.load(CORNELL, sampler="nope")
        with self.assertRaisesRegex(ValueError, "^width: "):
            penumbra.load(CORNELL, width=-3)
        scene = penumbra.load(CORNELL, width=16, height=12)
        with self.assertRaisesRegex(ValueError, "^aov: unknown AOV 'colour'"):
            scene.render(aov="colour")
        with self.assertRaisesRegex(ValueError, "denoise needs at least 2"):
            scene.render(denoise=True, spp=1)

    def test_options_come_from_the_cli_table(self):
        options = penumbra.options()
        self.assertEqual(options["spp"]["flag"], "--spp")
        self.assertIn("orbit", options["views"]["help"])
        # A flag without a job key (--threads) is a keyword too; numpy values work.
        image = penumbra.load(CORNELL, width=8, height=6, threads=np.int64(1)).render(
            spp=np.int32(1))
        self.assertEqual(image["rgba"].shape, (6, 8, 4))


class Gil(unittest.TestCase):
    def test_another_thread_runs_while_a_scene_renders(self):
        scene = penumbra.load(CORNELL, width=96, height=72, threads=1)
        ticks = []
        stop = threading.Event()

        def tick():
            while not stop.is_set():
                ticks.append(time.perf_counter())
                time.sleep(0.001)

        thread = threading.Thread(target=tick)
        thread.start()
        spp = 32
        while True:  # doubled until a render lasts long enough to tell, on any machine
            t0 = time.perf_counter()
            scene.render(spp=spp)
            t1 = time.perf_counter()
            if t1 - t0 > 0.3 or spp >= 1 << 14:
                break
            spp *= 2
        stop.set()
        thread.join()
        self.assertGreater(t1 - t0, 0.3, "too short a render to tell")
        # Holding the GIL, the render would leave no tick between its start and its end.
        during = [t for t in ticks if t0 + 0.02 < t < t1 - 0.02]
        self.assertGreater(len(during), 20)

    def test_ctrl_c_stops_a_render_with_keyboard_interrupt(self):
        scene = penumbra.load(CORNELL, width=96, height=72)
        timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
        timer.start()
        t0 = time.perf_counter()
        with self.assertRaises(KeyboardInterrupt):
            # Hours of samples; the time limit ends it (without KeyboardInterrupt: a failure)
            # should the signal not reach the render.
            scene.render(spp=1 << 20, time_limit=20)
        timer.join()
        self.assertLess(time.perf_counter() - t0, 15)  # stopped by the signal, not the limit
        # Python's own handler is back, and the scene renders on.
        self.assertEqual(scene.render(spp=1)["spp"], 1)
        with self.assertRaises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1)


if __name__ == "__main__":
    unittest.main()
