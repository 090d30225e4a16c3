#!/usr/bin/env python3
"""Writes the alpha-masked test scenes and their opaque twins into content/scenes/:

  masked_fence.gltf   a floor slab and a fence 6 m wide, 2 m high: ONE double-sided quad
                      whose base-color texture (96 x 32 texels, 6.25 cm each) has a binary
                      alpha: vertical slats 3 texels wide with 3-texel gaps, two horizontal
                      rails, the two bottom rows open. alphaMode MASK, alphaCutoff 0.5;
                      sampler LINEAR / LINEAR_MIPMAP_LINEAR / CLAMP_TO_EDGE.
  opaque_fence.gltf   the same fence as geometry: one double-sided quad per slat and per
                      rail (the rails overlap the slats, so the union has no T-junction
                      cracks), on the texel boundaries.
  masked_canopy.gltf  60 leaf quads (0.5 m, 64 x 64 texture, a binary-alpha ellipse) 2.5-3 m
                      over the floor, turned and tilted pseudo-randomly with a fixed seed.
  opaque_canopy.gltf  each leaf as a 24-gon fan of the same ellipse.

Each scene has a spot, a directional and a point light (KHR_lights_punctual, named) and one
named camera that sees the floor shadows.

Why the twins are the reference: with LINEAR magnification and a binary alpha, the bilinear
alpha crosses the 0.5 cutoff exactly on the texel boundaries, except within half a texel of
a corner of the opaque region, where bilinear interpolation rounds the corner (a convex
corner loses, a concave one gains, 0.097 texel^2). The fence twin is therefore exact but
at its corners: 4 concave ones per slat-rail junction, 2 convex ones at each slat's foot
(the quad's borders are no corners: CLAMP_TO_EDGE repeats the edge texel). The leaf twin
differs from the texel staircase of its ellipse by under a texel along the outline (the
script prints the share of the leaf's area that differs). The fence texture is 96 x 32, not a
power of two (the Khronos validator says so as an info); OpenGL 4.5 mipmaps it as it is.
Minification (mipmaps) blurs the alpha and moves the iso-line further; that is what a masked
depth pass sees when a map texel covers several texture texels, and part of what the bench
measures.

Run from anywhere: python3 tools/scripts/make_masked_scenes.py [OUT_DIR]
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import (CLAMP_TO_EDGE, LINEAR, LINEAR_MIPMAP_LINEAR, GltfBuilder, box,  # noqa: E402
                          output_dir, png_rgba)

SAMPLER = {"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR, "wrapS": CLAMP_TO_EDGE, "wrapT": CLAMP_TO_EDGE}
ALPHA_CUTOFF = 0.5
# Shadow settings every light starts with (the bench and --light override them).
SPOT_SHADOW = {"variant": "standard", "resolution": 2048, "filter": "pcf"}
SUN_SHADOW = {"variant": "standard", "resolution": 2048, "filter": "pcf"}
POINT_SHADOW = {"variant": "standard", "resolution": 1024, "filter": "pcf"}

# --- the fence -------------------------------------------------------------------------
FENCE_WIDTH, FENCE_HEIGHT = 6.0, 2.0          # metres, in the plane z = 0, x in [-3, 3], y in [0, 2]
FENCE_TEXELS = (96, 32)                        # 6.25 cm per texel both ways
FENCE_COLOR = (196, 150, 104)                  # sRGB of every texel, opaque or not (no colour bleed)
SLAT_PERIOD, SLAT_WIDTH, SLAT_FIRST = 6, 3, 1  # slats at columns 6k+1 .. 6k+3
SLAT_ROWS = (0, 30)                            # slats from the top row to row 29: rows 30, 31 open
RAIL_ROWS = [(6, 9), (21, 24)]                 # two rails, rows [6, 9) and [21, 24), full width


def fence_slat_columns():
    """[first, end) texel columns of each slat."""
    columns = []
    for start in range(SLAT_FIRST, FENCE_TEXELS[0], SLAT_PERIOD):
        columns.append((start, min(start + SLAT_WIDTH, FENCE_TEXELS[0])))
    return columns


def fence_opaque_rects():
    """The opaque texels as rectangles (column0, column1, row0, row1), ends exclusive: each
    slat over its full height, each rail over the full width (the union is the mask)."""
    rects = [(c0, c1, SLAT_ROWS[0], SLAT_ROWS[1]) for c0, c1 in fence_slat_columns()]
    rects += [(0, FENCE_TEXELS[0], r0, r1) for r0, r1 in RAIL_ROWS]
    return rects


def fence_texture():
    width, height = FENCE_TEXELS
    opaque = [[False] * width for _ in range(height)]
    for c0, c1, r0, r1 in fence_opaque_rects():
        for row in range(r0, r1):
            for column in range(c0, c1):
                opaque[row][column] = True
    rows = [[FENCE_COLOR + ((255 if opaque[r][c] else 0),) for c in range(width)] for r in range(height)]
    return png_rgba(width, height, rows)


def fence_point(column, row):
    """Texel corner (column, row), row 0 at the top, to a point of the fence plane."""
    return (-FENCE_WIDTH / 2 + column * FENCE_WIDTH / FENCE_TEXELS[0], FENCE_HEIGHT - row * FENCE_HEIGHT / FENCE_TEXELS[1],
            0.0)


def fence_rect_quad(c0, c1, r0, r1):
    """A quad facing +Z over texel columns [c0, c1), rows [r0, r1), with the matching UVs."""
    corners = [(c0, r1), (c1, r1), (c1, r0), (c0, r0)]  # counter-clockwise seen from +Z
    positions = [list(fence_point(c, r)) for c, r in corners]
    uvs = [[c / FENCE_TEXELS[0], r / FENCE_TEXELS[1]] for c, r in corners]
    return positions, [[0.0, 0.0, 1.0]] * 4, uvs


def merged(parts):
    """One triangle list of several (positions, normals, uvs) quads or fans given with their
    own (local) indices."""
    positions, normals, uvs, indices = [], [], [], []
    for part_positions, part_normals, part_uvs, part_indices in parts:
        base = len(positions)
        positions += part_positions
        normals += part_normals
        uvs += part_uvs
        indices += [base + i for i in part_indices]
    return positions, normals, uvs, indices


def add_floor(g):
    floor = g.material("floor", (0.75, 0.75, 0.72), roughness=0.9)
    g.node("floor", translation=(0, -0.1, 0), mesh=g.mesh("floor", box((20, 0.2, 20)), floor))


def fence_scene(masked):
    g = GltfBuilder()
    add_floor(g)
    if masked:
        texture = g.texture("fence_mask", fence_texture(), SAMPLER)
        material = g.material("fence_masked", (1.0, 1.0, 1.0), roughness=0.8, double_sided=True,
                              base_color_texture=texture, alpha_mode="MASK", alpha_cutoff=ALPHA_CUTOFF)
        positions, normals, uvs = fence_rect_quad(0, FENCE_TEXELS[0], 0, FENCE_TEXELS[1])
        g.node("fence", mesh=g.mesh("fence", (positions, normals, [0, 1, 2, 0, 2, 3]), material, texcoords=uvs))
    else:
        # The texture's colour (sRGB) as a linear factor, so both fences look alike.
        linear = tuple((c / 255.0) ** 2.2 for c in FENCE_COLOR)
        material = g.material("fence_opaque", linear, roughness=0.8, double_sided=True)
        quads = [fence_rect_quad(*rect) + ([0, 1, 2, 0, 2, 3],) for rect in fence_opaque_rects()]
        positions, normals, _, indices = merged(quads)
        g.node("fence", mesh=g.mesh("fence", (positions, normals, indices), material))

    # Behind the fence is -Z, the camera and the shadows in front (+Z).
    g.camera("main_camera", eye=(2.9, 4.0, 8.6), target=(0.0, 0.2, 2.3), yfov=0.75, znear=0.1, zfar=60.0)
    g.light("spot_light", "spot", eye=(0.6, 3.2, -3.5), target=(0.0, 0.0, 2.8), color=(1.0, 0.92, 0.8),
            intensity=110.0, inner=0.4, outer=0.55, shadow=SPOT_SHADOW)
    elevation, azimuth = math.radians(35.0), math.radians(20.0)
    toward_sun = (math.sin(azimuth) * math.cos(elevation), math.sin(elevation), -math.cos(azimuth) * math.cos(elevation))
    g.light("sun", "directional", eye=tuple(10.0 * c + t for c, t in zip(toward_sun, (0.0, 0.0, 1.0))),
            target=(0.0, 0.0, 1.0), color=(0.9, 0.95, 1.0), intensity=2.0, shadow=SUN_SHADOW)
    g.light("point_light", "point", eye=(-0.4, 2.5, -1.8), target=(-0.4, 0.0, -1.8), color=(1.0, 0.75, 0.45),
            intensity=30.0, range_=25.0, shadow=POINT_SHADOW)
    return g


# --- the canopy ------------------------------------------------------------------------
LEAF_COUNT, LEAF_SEED = 60, 20261201
LEAF_SIZE = 0.5                      # metres, the quad's side
LEAF_TEXELS = 64                     # 64 x 64: 7.8 mm per texel
LEAF_SEMI_AXES = (30.0, 15.0)        # texels, the ellipse's half length (along u) and half width
LEAF_COLOR = (92, 150, 60)
LEAF_POLYGON_SIDES = 24
CANOPY_RADIUS, CANOPY_HEIGHTS, LEAF_MAX_TILT = 2.0, (2.5, 3.0), math.radians(35.0)


def inside_leaf(u, v):
    """Whether texture point (u, v) in texels from the top-left corner is inside the ellipse."""
    a, b = LEAF_SEMI_AXES
    x, y = u - LEAF_TEXELS / 2, v - LEAF_TEXELS / 2
    return (x / a) ** 2 + (y / b) ** 2 <= 1.0


def leaf_alpha():
    """Binary alpha per texel: 1 where the texel's centre lies inside the ellipse."""
    return [[1 if inside_leaf(c + 0.5, r + 0.5) else 0 for c in range(LEAF_TEXELS)] for r in range(LEAF_TEXELS)]


def leaf_texture():
    return png_rgba(LEAF_TEXELS, LEAF_TEXELS, [[LEAF_COLOR + (255 * a,) for a in row] for row in leaf_alpha()])


def leaf_polygon_scale():
    """Radial scale of the inscribed n-gon that gives it the ellipse's area."""
    n = LEAF_POLYGON_SIDES
    return math.sqrt(math.pi / (n / 2 * math.sin(2 * math.pi / n)))


def leaf_polygon_texels():
    a, b = LEAF_SEMI_AXES
    s = leaf_polygon_scale()
    return [(LEAF_TEXELS / 2 + s * a * math.cos(2 * math.pi * i / LEAF_POLYGON_SIDES),
             LEAF_TEXELS / 2 + s * b * math.sin(2 * math.pi * i / LEAF_POLYGON_SIDES)) for i in range(LEAF_POLYGON_SIDES)]


def outline_mismatch():
    """The fraction of the leaf's area where the bilinearly filtered mask (cutoff 0.5, level 0,
    clamp) and the polygon disagree, sampled on a grid 8 x finer than the texels."""
    alpha = leaf_alpha()
    polygon = leaf_polygon_texels()
    n = LEAF_TEXELS

    def texel(c, r):
        return alpha[min(max(r, 0), n - 1)][min(max(c, 0), n - 1)]

    def bilinear(u, v):
        x, y = u - 0.5, v - 0.5
        c, r = math.floor(x), math.floor(y)
        fx, fy = x - c, y - r
        return ((1 - fx) * (1 - fy) * texel(c, r) + fx * (1 - fy) * texel(c + 1, r) +
                (1 - fx) * fy * texel(c, r + 1) + fx * fy * texel(c + 1, r + 1))

    def in_polygon(u, v):
        inside = False
        for i in range(len(polygon)):
            (x0, y0), (x1, y1) = polygon[i], polygon[i - 1]
            if (y0 > v) != (y1 > v) and u < x0 + (v - y0) * (x1 - x0) / (y1 - y0):
                inside = not inside
        return inside

    steps = 8 * n
    differ = masked = 0
    for i in range(steps):
        for j in range(steps):
            u, v = (i + 0.5) * n / steps, (j + 0.5) * n / steps
            m = bilinear(u, v) >= ALPHA_CUTOFF
            masked += m
            differ += m != in_polygon(u, v)
    return differ / masked


def rotation_matrix(yaw, tilt_axis_angle, tilt):
    """Yaw about +Y, after a tilt by `tilt` about the horizontal axis at `tilt_axis_angle`."""
    ax, az = math.cos(tilt_axis_angle), math.sin(tilt_axis_angle)
    c, s = math.cos(tilt), math.sin(tilt)
    # Rodrigues about (ax, 0, az).
    tilt_m = [[c + ax * ax * (1 - c), -az * s, ax * az * (1 - c)],
              [az * s, c, -ax * s],
              [az * ax * (1 - c), ax * s, c + az * az * (1 - c)]]
    cy, sy = math.cos(yaw), math.sin(yaw)
    yaw_m = [[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]]
    return [[sum(tilt_m[i][k] * yaw_m[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def leaf_placements():
    """(centre, rotation) of every leaf, from a fixed seed: the same file every run."""
    rng = random.Random(LEAF_SEED)
    leaves = []
    while len(leaves) < LEAF_COUNT:
        x, z = rng.uniform(-CANOPY_RADIUS, CANOPY_RADIUS), rng.uniform(-CANOPY_RADIUS, CANOPY_RADIUS)
        if x * x + z * z > CANOPY_RADIUS ** 2:
            continue
        y = rng.uniform(*CANOPY_HEIGHTS)
        yaw = rng.uniform(0.0, 2 * math.pi)
        tilt_axis, tilt = rng.uniform(0.0, 2 * math.pi), rng.uniform(0.0, LEAF_MAX_TILT)
        leaves.append(((x, y, z), rotation_matrix(yaw, tilt_axis, tilt)))
    return leaves


def leaf_local(u, v):
    """Texture point (texels) to the leaf's own frame: the quad in XZ facing +Y, u along +X,
    v along +Z (the quad of gltf_builder.quad, counter-clockwise seen from +Y)."""
    return [(u / LEAF_TEXELS - 0.5) * LEAF_SIZE, 0.0, (v / LEAF_TEXELS - 0.5) * LEAF_SIZE]


def leaf_part(centre, rotation, texel_points, indices):
    positions = [[p + c for p, c in zip(apply(rotation, leaf_local(u, v)), centre)] for u, v in texel_points]
    normal = apply(rotation, [0.0, 1.0, 0.0])
    uvs = [[u / LEAF_TEXELS, v / LEAF_TEXELS] for u, v in texel_points]
    return positions, [normal] * len(positions), uvs, indices


def canopy_scene(masked):
    g = GltfBuilder()
    add_floor(g)
    parts = []
    for centre, rotation in leaf_placements():
        if masked:
            n = LEAF_TEXELS
            parts.append(leaf_part(centre, rotation, [(0, n), (n, n), (n, 0), (0, 0)], [0, 1, 2, 0, 2, 3]))
        else:
            # A fan around the centre: counter-clockwise seen from +Y as the quad is.
            ring = leaf_polygon_texels()
            points = [(LEAF_TEXELS / 2, LEAF_TEXELS / 2)] + ring[::-1]
            fan = []
            for i in range(LEAF_POLYGON_SIDES):
                fan += [0, 1 + i, 1 + (i + 1) % LEAF_POLYGON_SIDES]
            parts.append(leaf_part(centre, rotation, points, fan))
    positions, normals, uvs, indices = merged(parts)
    if masked:
        texture = g.texture("leaf_mask", leaf_texture(), SAMPLER)
        material = g.material("leaf_masked", (1.0, 1.0, 1.0), roughness=0.7, double_sided=True,
                              base_color_texture=texture, alpha_mode="MASK", alpha_cutoff=ALPHA_CUTOFF)
        g.node("canopy", mesh=g.mesh("canopy", (positions, normals, indices), material, texcoords=uvs))
    else:
        linear = tuple((c / 255.0) ** 2.2 for c in LEAF_COLOR)
        material = g.material("leaf_opaque", linear, roughness=0.7, double_sided=True)
        g.node("canopy", mesh=g.mesh("canopy", (positions, normals, indices), material))

    g.camera("main_camera", eye=(4.0, 4.4, 5.0), target=(0.0, 0.0, 0.4), yfov=0.8, znear=0.1, zfar=60.0)
    g.light("spot_light", "spot", eye=(1.5, 7.5, 1.0), target=(0.0, 0.0, 0.3), color=(1.0, 0.92, 0.8),
            intensity=110.0, inner=0.35, outer=0.5, shadow=SPOT_SHADOW)
    elevation, azimuth = math.radians(70.0), math.radians(-30.0)
    toward_sun = (math.sin(azimuth) * math.cos(elevation), math.sin(elevation), -math.cos(azimuth) * math.cos(elevation))
    g.light("sun", "directional", eye=tuple(10.0 * c for c in toward_sun), target=(0.0, 0.0, 0.0),
            color=(0.9, 0.95, 1.0), intensity=2.0, shadow=SUN_SHADOW)
    g.light("point_light", "point", eye=(-0.3, 5.2, -0.4), target=(-0.3, 0.0, -0.4), color=(1.0, 0.75, 0.45),
            intensity=50.0, range_=25.0, shadow=POINT_SHADOW)
    return g


def main():
    # An optional output directory (the validation test writes to a scratch one).
    out_dir = output_dir(sys.argv)
    for name, builder in [("masked_fence", fence_scene(True)), ("opaque_fence", fence_scene(False)),
                          ("masked_canopy", canopy_scene(True)), ("opaque_canopy", canopy_scene(False))]:
        builder.write(os.path.join(out_dir, name + ".gltf"), name + ".bin")
    print("leaf twin: %d-gon, area matched; differs from the filtered mask in %.2f%% of the leaf's area"
          % (LEAF_POLYGON_SIDES, 100.0 * outline_mismatch()))


if __name__ == "__main__":
    main()
