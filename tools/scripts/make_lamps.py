#!/usr/bin/env python3
"""Writes content/scenes/lamps.gltf (+ .bin): a courtyard at night lit by four lamps.

A floor slab with pillars and benches under four shadowed spot lamps of narrow cones and
limited range: each lamp lights a small part of the view, the case where the lit pass
looks a light's shadow up only inside the light's screen footprint (README, "Skipping
work"). Run from the repository root: python3 tools/scripts/make_lamps.py [OUT_DIR]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, output_dir, box, icosphere  # noqa: E402


def main():
    out_dir = output_dir(sys.argv)
    g = GltfBuilder()
    stone = g.material("stone", (0.6, 0.6, 0.58), roughness=0.85)
    brick = g.material("brick", (0.65, 0.3, 0.2), roughness=0.7)
    wood = g.material("wood", (0.55, 0.38, 0.2), roughness=0.7)
    brass = g.material("brass", (0.85, 0.65, 0.3), metallic=0.9, roughness=0.3)

    g.node("floor", translation=(0, -0.1, 0), mesh=g.mesh("floor", box((30, 0.2, 30)), stone))
    pillar = g.mesh("pillar", box((0.5, 3.0, 0.5)), brick)
    bench = g.mesh("bench", box((1.6, 0.45, 0.5)), wood)
    ball = g.mesh("ball", icosphere(0.35, 2), brass)
    for row, z in enumerate((-6.0, 0.0, 6.0)):
        for column, x in enumerate((-9.0, -3.0, 3.0, 9.0)):
            name = "r%dc%d" % (row, column)
            g.node("pillar_" + name, translation=(x, 1.5, z), mesh=pillar)
            g.node("bench_" + name, translation=(x + 1.4, 0.225, z + 0.8), mesh=bench)
            g.node("ball_" + name, translation=(x - 1.0, 0.35, z + 1.2), mesh=ball)
    # Each lamp beside a pillar, aimed past it, so the pillar, a bench and a ball shadow its pool.
    for index, (x, z) in enumerate(((-4.6, -4.6), (1.4, 1.4), (7.4, -4.6), (-4.6, 7.4))):
        g.light("lamp_%d" % index, "spot", eye=(x, 4.0, z), target=(x - 1.6, 0.0, z - 1.0), color=(1.0, 0.85, 0.6),
                intensity=120.0, range_=9.0, inner=0.35, outer=0.6,
                shadow={"variant": "standard", "resolution": 1024, "filter": "pcf"})
    g.camera("main_camera", eye=(13.0, 9.0, 15.0), target=(0, 0, -1.0), yfov=0.8, znear=0.1, zfar=80.0)
    g.write(os.path.join(out_dir, "lamps.gltf"), "lamps.bin")


if __name__ == "__main__":
    main()
