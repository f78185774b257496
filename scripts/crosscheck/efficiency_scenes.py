"""The scenes of scripts/crosscheck/efficiency.py, made into files both renderers read: what
each is, how penumbra lights it and how Cycles builds its materials and world.

- cornell: scenes/cornell-box.gltf with the mirror sphere made Lambertian (albedo 0.75), so
  the whole box is Lambertian under its area light (the equal-error scene); Cycles
  gets exact Diffuse/Emission nodes (cycles_render.py's rebuild).
- helmet: ../shared/scenes/wild/FlightHelmet (Khronos sample, 5 textured materials with
  normal maps) under an equirectangular sky with a sun (sky_map()); Cycles through the
  importer's Principled BSDF, the same image as its world (Closest texel).
- glossy: scenes/glossy.gltf, gold and silver GGX spheres of roughness 0.05-0.6 lit by an
  emissive strip; Cycles through the importer (Principled, metallic 1).
- many-lights: scripts/make_many_lights.py's 10,000 emissive triangles; exact materials.
- many-lights-hall: its --layout hall (10,000 single-sided emitters on a 32 m hall's
  ceiling, where each point sees mostly the few above it) with the grey receivers made
  Lambertian; exact materials. Cycles 3.4 has no light tree: it picks emitters by power
  alone, as penumbra's --light-sampler power. Not in --quick.
"""
import hashlib
import json
import math
import os
import subprocess
import sys

from efficiency_metrics import write_pfm

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "scenes")

# name -> how Cycles builds the materials and the world (penumbra reads the file as it is).
SCENES = {
    "cornell": {"materials": "exact", "world": None},
    "helmet": {"materials": "importer", "world": "sky"},
    "glossy": {"materials": "importer", "world": None},
    "many-lights": {"materials": "exact", "world": None},
    "many-lights-hall": {"materials": "exact", "world": None},
    # Only for the Embree-tutorial comparison (efficiency_embree.py): the point light.
    "cornell-point": {"materials": "exact", "world": None},
    # penumbra only, for the same table: Embree's tutorial scene (embree_cornell.py).
    "embree-cornell": {"materials": "exact", "world": None},
}
ALL = ["cornell", "helmet", "glossy", "many-lights", "many-lights-hall"]
QUICK = ["cornell", "helmet", "glossy", "many-lights"]
SKY_SIZE = (256, 128)
SUN = {"elevation": 40.0, "azimuth": 60.0, "radius": 3.0, "radiance": 100.0}


def file_hash(paths):
    h = hashlib.sha256()
    for p in paths:
        with open(p, "rb") as f:
            h.update(f.read())
    return h.hexdigest()[:12]


def sky_rgb(theta, phi):
    """Radiance of the sky map in a direction: a blue gradient above the horizon, brown
    ground below, and a sun disk of SUN's radius (degrees) and radiance."""
    s = SUN
    el, az = math.radians(s["elevation"]), math.radians(s["azimuth"])
    # Direction of the sample and of the sun, in the map's own (theta from +Y, phi) terms.
    d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
    sun = (math.cos(el) * math.cos(az), math.sin(el), math.cos(el) * math.sin(az))
    if sum(a * b for a, b in zip(d, sun)) > math.cos(math.radians(s["radius"])):
        return [s["radiance"], 0.95 * s["radiance"], 0.85 * s["radiance"]]
    elev = math.pi / 2 - theta
    if elev <= 0:
        return [0.12, 0.1, 0.08]
    t = math.sin(elev)
    return [(0.6 + 0.2 * (1 - t)) * (0.4 + 0.6 * t), (0.75 + 0.1 * (1 - t)) * (0.4 + 0.6 * t),
            0.4 + 0.6 * t]


def sky_map(path):
    """Writes the equirectangular sky (texel centres, row 0 at the top, +Y up) as EXR."""
    w, h = SKY_SIZE
    rgb = []
    for j in range(h):
        theta = math.pi * (j + 0.5) / h
        for i in range(w):
            rgb += sky_rgb(theta, 2 * math.pi * (i + 0.5) / w)
    pfm = path + ".pfm"
    write_pfm(pfm, w, h, rgb)
    subprocess.run(["oiiotool", pfm, "-d", "float", "-o", path], check=True, capture_output=True)
    os.remove(pfm)


def without_specular(doc, material):
    """Makes a metallic-0 glTF material Lambertian (KHR_materials_specular factor 0), which
    Cycles' exact rebuild turns into a Diffuse BSDF (efficiency_cycles.py)."""
    material.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0.0}
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_materials_specular" not in used:
        used.append("KHR_materials_specular")


def lambertian_cornell(path):
    doc = json.load(open(os.path.join(ROOT, "scenes", "cornell-box.gltf")))
    for m in doc["materials"]:
        if m.get("name") == "mirror":
            m["pbrMetallicRoughness"] = {"baseColorFactor": [0.75, 0.75, 0.75, 1.0],
                                         "metallicFactor": 0.0, "roughnessFactor": 1.0}
            without_specular(doc, m)
    with open(path, "w") as f:
        json.dump(doc, f)


def lambertian_hall(path):
    """make_many_lights.py --layout hall with its non-emissive materials (the grey, albedo
    0.7) made Lambertian, so that both renderers see the same receivers."""
    made = path + ".tmp"
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_many_lights.py"), made,
                    "--layout", "hall"], check=True)
    doc = json.load(open(made))
    os.remove(made)
    for m in doc["materials"]:
        if max(m.get("emissiveFactor", [0, 0, 0])) == 0:
            without_specular(doc, m)
    with open(path, "w") as f:
        json.dump(doc, f)


def prepare(name, work_dir):
    """The scene's files under work_dir (made once): {"scene", "env" (or None), "hash"}, the
    hash covering everything that decides the image."""
    os.makedirs(work_dir, exist_ok=True)
    env = None
    if name == "cornell":
        scene = os.path.join(work_dir, "cornell-lambertian.gltf")
        if not os.path.exists(scene):
            lambertian_cornell(scene)
        deps = [scene]
    elif name == "helmet":
        scene = os.path.join(SHARED, "wild", "FlightHelmet", "FlightHelmet.gltf")
        env = os.path.join(work_dir, "sky.exr")
        if not os.path.exists(env):
            sky_map(env)
        deps = [scene, os.path.join(os.path.dirname(scene), "FlightHelmet.bin"), env]
    elif name == "cornell-point":
        scene = os.path.join(ROOT, "scenes", "cornell-box-point.gltf")
        deps = [scene]
    elif name == "embree-cornell":
        # Embree's tutorial scene itself (embree_cornell.py), for the equal-spp table.
        scene = os.path.join(work_dir, "embree-cornell.gltf")
        if not os.path.exists(scene):
            subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "crosscheck",
                                                         "embree_cornell.py"), scene], check=True)
        deps = [scene]
    elif name == "glossy":
        scene = os.path.join(ROOT, "scenes", "glossy.gltf")
        deps = [scene]
    elif name == "many-lights":
        scene = os.path.join(work_dir, "many-lights.gltf")
        if not os.path.exists(scene):
            subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_many_lights.py"),
                            scene], check=True)
        deps = [scene]
    elif name == "many-lights-hall":
        scene = os.path.join(work_dir, "many-lights-hall.gltf")
        if not os.path.exists(scene):
            lambertian_hall(scene)
        deps = [scene]
    else:
        raise ValueError("unknown scene %r (known: %s)" % (name, ", ".join(SCENES)))
    return {"scene": scene, "env": env, "hash": file_hash(deps)}


def penumbra_lighting(prepared):
    """penumbra's lighting arguments: the file's own lights and emitters, no default lights,
    plus the environment image where the scene has one."""
    args = ["--no-default-light"]
    if prepared["env"]:
        args += ["--env", prepared["env"]]
    return args


def cycles_world(name, prepared):
    return prepared["env"] if SCENES[name]["world"] == "sky" else None
