"""Helpers for the scene generator scripts: a glTF 2.0 buffer/accessor builder and
simple meshes (quads, a unit cube, a UV sphere). Output is a single .gltf with the
buffer embedded as a data: URI."""
import base64
import math
import struct

# KHR_lights_punctual intensities are photometric (candela, lux) and penumbra converts
# them at 683 lm/W. The scenes state their lights radiometrically (W/sr, W/m^2) and write
# photometric(x); 683 x a round number divides back exactly.
LUMENS_PER_WATT = 683.0


def photometric(radiometric):
    """candela for a radiant intensity in W/sr, lux for an irradiance in W/m^2."""
    return radiometric * LUMENS_PER_WATT


class Builder:
    def __init__(self):
        self.blob = bytearray()
        self.views = []
        self.accessors = []

    def _view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.views.append(view)
        self.blob += data
        return len(self.views) - 1

    def vec3(self, values):
        data = b"".join(struct.pack("<3f", *v) for v in values)
        lo = [min(v[i] for v in values) for i in range(3)]
        hi = [max(v[i] for v in values) for i in range(3)]
        self.accessors.append({"bufferView": self._view(data, 34962), "componentType": 5126,
                               "count": len(values), "type": "VEC3", "min": lo, "max": hi})
        return len(self.accessors) - 1

    def vec4(self, values):
        data = b"".join(struct.pack("<4f", *v) for v in values)
        self.accessors.append({"bufferView": self._view(data, None), "componentType": 5126,
                               "count": len(values), "type": "VEC4"})
        return len(self.accessors) - 1

    def indices32(self, values):
        data = struct.pack("<%dI" % len(values), *values)
        self.accessors.append({"bufferView": self._view(data, 34963), "componentType": 5125,
                               "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def indices(self, values):
        data = struct.pack("<%dH" % len(values), *values)
        self.accessors.append({"bufferView": self._view(data, 34963), "componentType": 5123,
                               "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def primitive(self, positions, normals, indices, material):
        return {"attributes": {"POSITION": self.vec3(positions), "NORMAL": self.vec3(normals)},
                "indices": self.indices(indices), "material": material}


def quad(corners, normal):
    """Two triangles, counter-clockwise as seen from the side the normal points to."""
    return corners, [normal] * 4, [0, 1, 2, 0, 2, 3]


def merge(quads):
    pos, nrm, idx = [], [], []
    for p, n, i in quads:
        base = len(pos)
        pos += p
        nrm += n
        idx += [base + k for k in i]
    return pos, nrm, idx


def unit_cube():
    """The cube [-0.5, 0.5]^3 with outward normals."""
    quads = []
    for axis in range(3):
        for sign in (-1, 1):
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            corners = []
            for a, b in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
                c = [0.0, 0.0, 0.0]
                c[axis] = 0.5 * sign
                c[u] = 0.5 * a
                c[v] = 0.5 * b * sign  # flip the winding on the negative side
                corners.append(c)
            n = [0.0, 0.0, 0.0]
            n[axis] = float(sign)
            quads.append(quad(corners, n))
    return merge(quads)


def uv_sphere(rings=24, segments=48):
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            pos.append(n)
            nrm.append(n)
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r != 0:
                idx += [a, b, a + 1]
            if r != rings - 1:
                idx += [a + 1, b, b + 1]
    return pos, nrm, idx


def y_rotation(deg):
    h = math.radians(deg) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


def buffers(builder):
    """The glTF "buffers" array for everything the builder wrote."""
    return [{"byteLength": len(builder.blob), "uri": "data:application/octet-stream;base64," +
             base64.b64encode(bytes(builder.blob)).decode("ascii")}]
