#!/usr/bin/env python3
"""Writes lobe-spheres.gltf: the 5 x 5 spheres of scenes/material-spheres.gltf (same
geometry, camera and lights) with one glTF material extension per row, its main
parameter swept 0, 0.25, 0.5, 0.75, 1 from left to right:

  top     KHR_materials_clearcoat: factor 1 over red rough plastic, clearcoatRoughness
          KHR_materials_sheen: warm sheen over dark blue, sheenRoughness
          KHR_materials_diffuse_transmission: green base, red transmission, the factor
          KHR_materials_specular: dark base, orange specularColor, specularFactor
  bottom  KHR_materials_pbrSpecularGlossiness: gold specular, glossiness 1 - x;
          the last sphere is KHR_materials_unlit (flat light blue)

With --page 2 it writes lobe-spheres-2.gltf instead:

  top     KHR_materials_iridescence: factor 1 over a dark dielectric, film thickness
          100 + 600 x nm
          KHR_materials_anisotropy: brushed metal (roughness 0.4), anisotropyStrength
          KHR_materials_volume: clear glass (transmission 1, thickness 1), blue
          attenuation at distance 4 (x = 0) down to 0.25 (x = 1) (x = 0: no absorption)
          KHR_materials_dispersion: clear glass with a volume, dispersion 20 x ... 0 to 1
  bottom  KHR_materials_transmission without a volume (thin-walled), roughness x

What to expect: the coat's sharp highlight spreads with its roughness over an unchanged
base; the sheen's rim narrows towards roughness 0; diffuse transmission darkens the lit
side and turns it red as light passes through; the specular row goes from plain diffuse
(factor 0, exactly Lambertian) to orange reflections.

Usage: tests/scripts/make_lobe_spheres.py OUT_DIR [--page 2], then
       build/bin/penumbra render OUT_DIR/lobe-spheres.gltf --width 320 --spp 64
"""
import copy
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SWEEP = [0.0, 0.25, 0.5, 0.75, 1.0]


def pbr(base, metallic=0.0, roughness=0.5):
    return {"baseColorFactor": base + [1.0], "metallicFactor": metallic,
            "roughnessFactor": roughness}


def row_materials(row, x):
    name = f"row{row}-{x:.2f}"
    if row == 0:
        return {"name": name, "pbrMetallicRoughness": pbr([0.6, 0.05, 0.05], roughness=0.6),
                "extensions": {"KHR_materials_clearcoat": {
                    "clearcoatFactor": 1.0, "clearcoatRoughnessFactor": x}}}
    if row == 1:
        return {"name": name, "pbrMetallicRoughness": pbr([0.03, 0.03, 0.2], roughness=0.8),
                "extensions": {"KHR_materials_sheen": {
                    "sheenColorFactor": [1.0, 0.8, 0.6], "sheenRoughnessFactor": x}}}
    if row == 2:
        return {"name": name, "pbrMetallicRoughness": pbr([0.2, 0.6, 0.2], roughness=0.6),
                "extensions": {"KHR_materials_diffuse_transmission": {
                    "diffuseTransmissionFactor": x,
                    "diffuseTransmissionColorFactor": [1.0, 0.3, 0.1]}}}
    if row == 3:
        return {"name": name, "pbrMetallicRoughness": pbr([0.05, 0.05, 0.05], roughness=0.3),
                "extensions": {"KHR_materials_specular": {
                    "specularFactor": x, "specularColorFactor": [1.0, 0.5, 0.2]}}}
    if x == 1.0:
        return {"name": name, "pbrMetallicRoughness": pbr([0.2, 0.5, 0.9]),
                "extensions": {"KHR_materials_unlit": {}}}
    return {"name": name, "extensions": {"KHR_materials_pbrSpecularGlossiness": {
        "diffuseFactor": [0.1, 0.1, 0.1, 1.0], "specularFactor": [1.0, 0.8, 0.3],
        "glossinessFactor": 1 - x}}}


def page2_materials(row, x):
    name = f"page2-row{row}-{x:.2f}"
    glass = {"KHR_materials_transmission": {"transmissionFactor": 1.0},
             "KHR_materials_volume": {"thicknessFactor": 1.0}}
    if row == 0:
        return {"name": name, "pbrMetallicRoughness": pbr([0.05, 0.05, 0.05], roughness=0.3),
                "extensions": {"KHR_materials_iridescence": {
                    "iridescenceFactor": 1.0, "iridescenceThicknessMaximum": 100 + 600 * x}}}
    if row == 1:
        return {"name": name,
                "pbrMetallicRoughness": pbr([0.9, 0.9, 0.9], metallic=1.0, roughness=0.4),
                "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": x}}}
    if row == 2:
        ext = copy.deepcopy(glass)
        if x > 0:
            ext["KHR_materials_volume"].update(
                {"attenuationColor": [0.2, 0.4, 0.9], "attenuationDistance": 0.25 / x})
        return {"name": name, "pbrMetallicRoughness": pbr([1, 1, 1], roughness=0.0),
                "extensions": ext}
    if row == 3:
        ext = copy.deepcopy(glass)
        ext["KHR_materials_dispersion"] = {"dispersion": x}
        ext["KHR_materials_ior"] = {"ior": 1.7}
        return {"name": name, "pbrMetallicRoughness": pbr([1, 1, 1], roughness=0.0),
                "extensions": ext}
    return {"name": name, "pbrMetallicRoughness": pbr([1, 1, 1], roughness=x),
            "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}}


def main():
    page2 = "--page" in sys.argv and sys.argv[sys.argv.index("--page") + 1] == "2"
    args = [a for a in sys.argv[1:] if a not in ("--page", "2")]
    if len(args) != 1:
        sys.exit(__doc__)
    materials = page2_materials if page2 else row_materials
    with open(os.path.join(ROOT, "scenes", "material-spheres.gltf")) as f:
        scene = json.load(f)
    out = copy.deepcopy(scene)
    # Sphere i (row i // 5 from the top, column i % 5) uses material i.
    out["materials"] = [materials(i // 5, SWEEP[i % 5]) for i in range(25)]
    for i, mesh in enumerate(out["meshes"]):
        for prim in mesh["primitives"]:
            prim["material"] = i
    used = set(out.get("extensionsUsed", []))
    for m in out["materials"]:
        used.update(m.get("extensions", {}).keys())
    out["extensionsUsed"] = sorted(used)
    os.makedirs(args[0], exist_ok=True)
    name = "lobe-spheres-2.gltf" if page2 else "lobe-spheres.gltf"
    with open(os.path.join(args[0], name), "w") as f:
        json.dump(out, f)


if __name__ == "__main__":
    main()
