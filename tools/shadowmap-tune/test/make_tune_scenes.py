#!/usr/bin/env python3
"""make_tune_scenes.py OUT_DIR: small scenes whose best shadow setting is known, for
shadowmap-tune's tests (written at test time, nothing checked in).

Every light pins normal_offset 0: the tuner chooses variant, size, format, filter and the
polygon offset, and these scenes' best choices were found with the depth bias alone (the
default normal offset changes which variant wins on closed.gltf: woo 0.412 % against
backface 0.42 %).

  closed.gltf  two closed boxes standing on a floor under one low spot light (grazing, so
               a polygon offset large enough against acne lifts the shadows off the boxes'
               feet): back faces are the caster's far side, so backface puts the depth
               comparison far from every lit surface and needs no offset.
  open.gltf    the same place with two open quads floating over the floor as casters:
               backface has no closed mesh to work on there.
  zero_offset.gltf  closed.gltf with the light set to standard at polygon offset [0, 0]:
               self-shadowing acne on every lit face, which an offset fit must remove.
  dark.gltf    closed.gltf without its light.
  two_lights.gltf  closed.gltf with a second spot light from the other side at polygon
               offset [0, 0] (acne): two lights that both change, for two shards.
Each has two cameras; the floor receives and casts nothing (it is open too).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from gltf_builder import GltfBuilder, box, quad  # noqa: E402


def scene(casters, light=True, shadow=None, second=None):
    b = GltfBuilder()
    grey = b.material("grey", (0.8, 0.8, 0.8))
    floor = b.mesh("floor", quad(8.0, 8.0), grey)
    b.node("floor", mesh=floor, extras={"cast_shadows": False})
    for name, geometry, position in casters:
        b.node(name, translation=position, mesh=b.mesh(name, geometry, grey))
    if light:
        b.light("spot", "spot", (5.0, 1.6, 2.0), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 60.0, inner=0.3, outer=0.6,
                shadow=shadow)
    if second is not None:
        b.light("spot_b", "spot", (-3.0, 5.0, -1.5), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 60.0, inner=0.3, outer=0.6,
                shadow=second)
    b.camera("front", (0.0, 5.0, 7.0), (0.0, 0.3, 0.0), 0.9, 0.1)
    b.camera("side", (7.0, 4.0, 1.0), (0.0, 0.3, 0.0), 0.9, 0.1)
    return b


def main():
    out = sys.argv[1]
    closed = [("box_a", box((1.0, 1.0, 1.0)), (-0.8, 0.5, 0.3)), ("box_b", box((0.6, 1.6, 0.6)), (1.0, 0.8, -0.6))]
    opened = [("card_a", quad(1.2, 1.2), (-0.8, 1.0, 0.3)), ("card_b", quad(0.8, 0.8), (1.0, 1.5, -0.6))]
    pinned = {"normal_offset": 0}
    scene(closed, shadow=pinned).write(os.path.join(out, "closed.gltf"), "closed.bin")
    scene(opened, shadow=pinned).write(os.path.join(out, "open.gltf"), "open.bin")
    scene(closed, shadow={**pinned, "variant": "standard", "polygon_offset": [0, 0]}).write(
        os.path.join(out, "zero_offset.gltf"), "zero_offset.bin")
    scene(closed, shadow={**pinned, "variant": "standard"},
          second={**pinned, "variant": "standard", "polygon_offset": [0, 0]}).write(
        os.path.join(out, "two_lights.gltf"), "two_lights.bin")
    scene(closed, light=False).write(os.path.join(out, "dark.gltf"), "dark.bin")


main()
