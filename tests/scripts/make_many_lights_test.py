"""Unit tests of scripts/make_many_lights.py, every layout: the emitter count, determinism,
the emission levels, and for the single-sided dome and hall the side each emitter faces.
Run by tests/scripts/make_many_lights_test.cpp:  python3 -m unittest make_many_lights_test
"""
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def make(out, *extra):
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_many_lights.py"),
                    out] + list(extra), check=True)
    with open(out) as f:
        return json.load(f)


def emitter_primitives(doc):
    emissive = {i for i, m in enumerate(doc["materials"])
                if max(m.get("emissiveFactor", [0, 0, 0])) > 0}
    return [p for mesh in doc["meshes"] for p in mesh["primitives"]
            if p["material"] in emissive], emissive


def triangle_count(doc, p):
    if "indices" in p:
        return doc["accessors"][p["indices"]]["count"] // 3
    return doc["accessors"][p["attributes"]["POSITION"]]["count"] // 3


def strengths(doc):
    return [m["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"]
            for m in doc["materials"] if "emissiveFactor" in m]


def positions(doc, p):
    """The unindexed POSITION floats of a primitive, as (x, y, z) tuples."""
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    acc = doc["accessors"][p["attributes"]["POSITION"]]
    view = doc["bufferViews"][acc["bufferView"]]
    start = view["byteOffset"] + acc.get("byteOffset", 0)
    return [struct.unpack_from("<3f", blob, start + 12 * k) for k in range(acc["count"])]


def front_normal(a, b, c):
    """The normal of the counter-clockwise (front) side, glTF's convention."""
    e1 = [b[j] - a[j] for j in range(3)]
    e2 = [c[j] - a[j] for j in range(3)]
    return [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0]]


class Layouts(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def check_count_and_determinism(self, layout, levels):
        a, b = self.path(layout + "-a.gltf"), self.path(layout + "-b.gltf")
        doc = make(a, "--layout", layout)
        make(b, "--layout", layout)
        with open(a, "rb") as fa, open(b, "rb") as fb:
            self.assertEqual(fa.read(), fb.read())
        prims, emissive = emitter_primitives(doc)
        self.assertEqual(sum(triangle_count(doc, p) for p in prims), 10000)
        self.assertEqual(len(emissive), levels)
        small = make(b, "--layout", layout, "--count", "123")
        self.assertEqual(sum(triangle_count(small, p) for p in emitter_primitives(small)[0]), 123)
        make(b, "--layout", layout, "--seed", "2")
        with open(a, "rb") as fa, open(b, "rb") as fb:
            self.assertNotEqual(fa.read(), fb.read())
        return doc

    def test_cloud_is_the_default_with_64_double_sided_materials_over_100x(self):
        doc = make(self.path("default.gltf"))
        self.assertEqual(doc, make(self.path("cloud.gltf"), "--layout", "cloud"))
        doc = self.check_count_and_determinism("cloud", 64)
        self.assertAlmostEqual(max(strengths(doc)) / min(strengths(doc)), 100.0, places=3)
        self.assertTrue(all(m.get("doubleSided") for m in doc["materials"]
                            if "emissiveFactor" in m))

    def check_single_sided_facing(self, doc, towards):
        """Every emitter is single-sided and its front faces towards(centroid); a flipped
        winding on any one triangle fails."""
        self.assertFalse(any(m.get("doubleSided") for m in doc["materials"]))
        prims = emitter_primitives(doc)[0]
        checked = 0
        for p in prims:
            pos = positions(doc, p)
            for k in range(0, len(pos), 3):
                tri = pos[k:k + 3]
                n = front_normal(*tri)
                centroid = [sum(v[j] for v in tri) / 3 for j in range(3)]
                d = towards(centroid)
                self.assertGreater(sum(n[j] * d[j] for j in range(3)), 0, (p, k))
                checked += 1
        self.assertEqual(checked, 10000)

    def test_dome_emitters_face_the_room_over_32_levels_from_0_1_to_50(self):
        doc = self.check_count_and_determinism("dome", 32)
        s = strengths(doc)
        self.assertAlmostEqual(min(s), 0.1, places=9)
        self.assertAlmostEqual(max(s), 50.0, places=9)
        self.check_single_sided_facing(doc, lambda c: [-c[0], 1.0 - c[1], -c[2]])
        for p in emitter_primitives(doc)[0]:  # all on the radius-3 dome around (0, 1, 0)
            acc = doc["accessors"][p["attributes"]["POSITION"]]
            self.assertGreater(acc["min"][1], 1.0 + 3.0 * 0.15 - 0.1)
            self.assertLess(max(abs(x) for x in acc["max"] + acc["min"]), 3.1 + 1.0)

    def test_hall_emitters_face_down_under_the_ceiling(self):
        doc = self.check_count_and_determinism("hall", 32)
        self.assertAlmostEqual(max(strengths(doc)) / min(strengths(doc)), 500.0, places=6)
        self.check_single_sided_facing(doc, lambda c: [0.0, -1.0, 0.0])
        for p in emitter_primitives(doc)[0]:
            acc = doc["accessors"][p["attributes"]["POSITION"]]
            self.assertAlmostEqual(acc["min"][1], 2.95, places=5)
            self.assertAlmostEqual(acc["max"][1], 2.95, places=5)
            self.assertGreaterEqual(acc["min"][0], -2.0)
            self.assertLessEqual(acc["max"][0], 2.0)
            self.assertGreaterEqual(acc["min"][2], -30.0)
            self.assertLessEqual(acc["max"][2], 2.0)

    def test_count_below_one_is_refused(self):
        r = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_many_lights.py"),
                            self.path("x.gltf"), "--count", "0"], capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("--count must be at least 1", r.stderr)


if __name__ == "__main__":
    unittest.main()
