#!/usr/bin/env python3
"""make_tune_scenes.py OUT_DIR: small scenes whose best shadow setting is known, for
shadowmap-tune's tests (written at test time, nothing checked in).

Every light pins normal_offset 0, still needed now that the tuner fits the normal offset:
it fits it only beside the polygon offset, for the best setting that draws with one, and
every other candidate keeps the light's own normal offset. The pin makes that 0, where the
variants differ (closed.gltf: backface 0.412 %, woo 0.427 % area error). At the default 0.25
standard, woo and backface all shade the same pixels there (0.412 %), and the known-best
test would compare ties, not variants.

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
  sized.gltf   closed.gltf with a spot light of radius 0.3 (SIZED_SETTING): ranked by its
               soft error, and pcss can follow its penumbra where hard filters cannot.
  sized_front.gltf, sized_side.gltf  sized.gltf seen by one of its two cameras each: what
               the two views pool from.
  grazing.gltf one box on the floor under a spot light 4.8 degrees over it (GRAZING_EYE),
               standard with its polygon offset clamped (GRAZING_CLAMP): the depth bias
               cannot grow with the floor's slope in the map, the floor shows acne, and
               only the normal offset removes it.
  refusing.gltf  closed.gltf lit by a spot light whose far plane is infinite and a sun warped
               by lispsm: lights that refuse vsm and evsm (their moments need a finite
               depth range, and depth linear in the distance from the light).
Each has two cameras (but sized_front, sized_side); the floor receives and casts nothing (it
is open too).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from gltf_builder import GltfBuilder, box, quad  # noqa: E402


# The sized light's setting in sized*.gltf: a size, and the one setting the pooling test
# measures (woo draws no polygon offset, so there is no fit: the first render is all).
SIZED_SETTING = {"light_radius": 0.3, "variant": "woo", "resolution": 512, "depth_format": "d24", "filter": "pcss",
                 "filter_taps": 8}
# grazing.gltf's light: 0.5 over the floor, 6 away, so it meets the floor at 4.8 degrees;
# its polygon_offset_clamp (window depth; not a key the tuner sets) stops the depth bias at
# about 17 steps of d24, as a light that keeps contact shadows tight under steep casters would.
GRAZING_EYE = (6.0, 0.5, 0.0)
GRAZING_CLAMP = 1e-6


def scene(casters, light=True, shadow=None, second=None, cameras=("front", "side"), eye=(5.0, 1.6, 2.0)):
    b = GltfBuilder()
    grey = b.material("grey", (0.8, 0.8, 0.8))
    floor = b.mesh("floor", quad(8.0, 8.0), grey)
    b.node("floor", mesh=floor, extras={"cast_shadows": False})
    for name, geometry, position in casters:
        b.node(name, translation=position, mesh=b.mesh(name, geometry, grey))
    if light:
        b.light("spot", "spot", eye, (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 60.0, inner=0.3, outer=0.6, shadow=shadow)
    if second is not None:
        b.light("spot_b", "spot", (-3.0, 5.0, -1.5), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 60.0, inner=0.3, outer=0.6,
                shadow=second)
    places = {"front": (0.0, 5.0, 7.0), "side": (7.0, 4.0, 1.0)}
    for name in cameras:
        b.camera(name, places[name], (0.0, 0.3, 0.0), 0.9, 0.1)
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
    sized = {**pinned, **SIZED_SETTING}
    for name, cameras in (("sized", ("front", "side")), ("sized_front", ("front",)), ("sized_side", ("side",))):
        scene(closed, shadow=sized, cameras=cameras).write(os.path.join(out, name + ".gltf"), name + ".bin")
    refusing = scene(closed, shadow={**pinned, "far_plane": "infinite"})
    refusing.light("sun", "directional", (4.0, 8.0, 3.0), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 2.0,
                   shadow={**pinned, "projection": "lispsm", "cascades": 1})
    refusing.write(os.path.join(out, "refusing.gltf"), "refusing.bin")
    scene(closed[:1], shadow={**pinned, "variant": "standard", "polygon_offset_clamp": GRAZING_CLAMP},
          eye=GRAZING_EYE).write(
        os.path.join(out, "grazing.gltf"), "grazing.bin")


main()
