"""Error and efficiency measures of scripts/crosscheck/efficiency.py, and reading images as
plain float lists (through oiiotool; standard library only, so any python3 runs it).

relMSE = mean over pixels and RGB channels of (x - ref)^2 / (ref^2 + EPSILON), the relative
MSE of the rendering literature (Rousselle et al. 2011; Bitterli's and pbrt-v4's tables),
and efficiency = 1 / (relMSE x seconds): for an unbiased renderer relMSE falls as 1 / spp,
so the efficiency does not depend on the spp and two renderers' ratio is the inverse ratio
of their times to the same error.
"""
import array
import os
import subprocess
import sys
import tempfile

# Keeps dark pixels (ref near 0) from dominating; 1e-2 as in pbrt-v4's imgtool and the
# adaptive-sampling papers that use relMSE (e.g. Rousselle et al.).
EPSILON = 1e-2


def write_pfm(path, width, height, rgb):
    """Writes RGB floats (row by row from the top) as a little-endian PFM."""
    data = array.array("f", rgb)
    if sys.byteorder != "little":
        data.byteswap()
    row = width * 3
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        for y in reversed(range(height)):
            data[y * row:(y + 1) * row].tofile(f)


def read_rgb(path):
    """(width, height, RGB floats row by row from the top) of any image oiiotool reads; alpha
    and AOVs dropped. Through oiiotool --dumpdata (9 significant digits, float-exact)."""
    with tempfile.TemporaryDirectory() as tmp:
        rgb = os.path.join(tmp, "rgb.exr")
        subprocess.run(["oiiotool", path, "--ch", "R,G,B", "-d", "float", "-o", rgb],
                       check=True, capture_output=True)
        text = subprocess.run(["oiiotool", "--dumpdata", rgb], check=True, capture_output=True,
                              text=True).stdout
    lines = text.splitlines()
    width, height = (int(v) for v in lines[0].split(":", 1)[1].split(",")[0].split(" x "))
    data = array.array("f")
    for line in lines[1:]:
        if "Pixel (" in line:
            data.extend(float(v) for v in line.split("):", 1)[1].split()[:3])
    if len(data) != 3 * width * height:
        raise ValueError("%s: read %d values, expected %d" % (path, len(data), 3 * width * height))
    return width, height, data


def average(a, b):
    return array.array("f", [0.5 * (x + y) for x, y in zip(a, b)])


def relmse(image, ref, eps=EPSILON):
    """Mean over pixels and channels of (x - ref)^2 / (ref^2 + eps)."""
    if len(image) != len(ref) or not ref:
        raise ValueError("images differ in size (%d and %d values)" % (len(image), len(ref)))
    return sum((x - r) ** 2 / (r * r + eps) for x, r in zip(image, ref)) / len(ref)


def reference_relmse(half_a, half_b, eps=EPSILON):
    """The relMSE of the reference (the average of two independent halves) against the exact
    image, estimated from the halves: Var(average) = E[(a - b)^2] / 4 per value. Measured
    relMSE against this reference is the true relMSE plus this (independent errors add),
    so it is subtracted and, when it is a large share, said."""
    ref = average(half_a, half_b)
    return sum((a - b) ** 2 / 4 / (r * r + eps) for a, b, r in zip(half_a, half_b, ref)) / len(ref)


def efficiency(rel_mse, seconds):
    """1 / (relMSE x seconds); infinite for an exact image (relMSE 0)."""
    if seconds <= 0:
        raise ValueError("time must be positive, got %r" % seconds)
    return float("inf") if rel_mse <= 0 else 1.0 / (rel_mse * seconds)


def median(values):
    v = sorted(values)
    if not v:
        raise ValueError("median of nothing")
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])
