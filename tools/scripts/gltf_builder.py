"""A small glTF 2.0 writer for the scenes we author in content/ (no dependencies).

Meshes are closed where they should be (boxes, icospheres, tori share positions along
every edge), so the loader's closedness check and the backface shadow variant see them as
closed. Geometry goes into one external .bin next to the .gltf; textures are PNGs written
here (png_rgba) and embedded as data URIs.
"""
import base64
import json
import math
import os
import struct
import zlib

# glTF sampler enumerants (the OpenGL ones).
NEAREST, LINEAR = 9728, 9729
LINEAR_MIPMAP_LINEAR = 9987
CLAMP_TO_EDGE, REPEAT = 33071, 10497


# Where the generators write unless given a directory: the repository's content/scenes.
CONTENT_SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "content", "scenes")


def output_dir(argv):
    """The directory a generator writes into: its first argument, else content/scenes."""
    return argv[1] if len(argv) > 1 else CONTENT_SCENES


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def look_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Quaternion (x, y, z, w) turning a node so its -Z looks from eye at target."""
    forward = normalize(sub(target, eye))
    if abs(sum(f * u for f, u in zip(forward, up))) > 0.999:
        up = (0.0, 0.0, -1.0) if forward[1] < 0 else (0.0, 0.0, 1.0)
    right = normalize(cross(forward, up))
    true_up = cross(right, forward)
    back = [-f for f in forward]
    # Columns of the rotation matrix: right, up, back (+Z points away from the view).
    m = [[right[0], true_up[0], back[0]], [right[1], true_up[1], back[1]], [right[2], true_up[2], back[2]]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = math.sqrt(trace + 1.0) * 2
        return [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    if m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        return [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    if m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        return [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
    return [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]


def box(size):
    """Axis-aligned box centred at the origin, 24 vertices (flat normals), closed by position."""
    hx, hy, hz = (s / 2 for s in size)
    faces = [  # normal, corner order counter-clockwise seen from outside
        ((1, 0, 0), [(hx, -hy, hz), (hx, -hy, -hz), (hx, hy, -hz), (hx, hy, hz)]),
        ((-1, 0, 0), [(-hx, -hy, -hz), (-hx, -hy, hz), (-hx, hy, hz), (-hx, hy, -hz)]),
        ((0, 1, 0), [(-hx, hy, hz), (hx, hy, hz), (hx, hy, -hz), (-hx, hy, -hz)]),
        ((0, -1, 0), [(-hx, -hy, -hz), (hx, -hy, -hz), (hx, -hy, hz), (-hx, -hy, hz)]),
        ((0, 0, 1), [(-hx, -hy, hz), (hx, -hy, hz), (hx, hy, hz), (-hx, hy, hz)]),
        ((0, 0, -1), [(hx, -hy, -hz), (-hx, -hy, -hz), (-hx, hy, -hz), (hx, hy, -hz)]),
    ]
    positions, normals, indices = [], [], []
    for normal, corners in faces:
        base = len(positions)
        positions += [list(c) for c in corners]
        normals += [list(normal)] * 4
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def icosphere(radius, subdivisions):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [normalize(v) for v in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                                    (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                verts.append(normalize([(x + y) / 2 for x, y in zip(verts[a], verts[b])]))
                cache[key] = len(verts) - 1
            return cache[key]
        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    positions = [[c * radius for c in v] for v in verts]
    return positions, [list(v) for v in verts], [i for f in faces for i in f]


def torus(major, minor, segments, sides):
    positions, normals, indices = [], [], []
    for i in range(segments):
        u = 2 * math.pi * i / segments
        for j in range(sides):
            v = 2 * math.pi * j / sides
            n = [math.cos(u) * math.cos(v), math.sin(v), math.sin(u) * math.cos(v)]
            positions.append([math.cos(u) * (major + minor * math.cos(v)), minor * math.sin(v),
                              math.sin(u) * (major + minor * math.cos(v))])
            normals.append(n)
    for i in range(segments):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % segments) * sides + j
            c = ((i + 1) % segments) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            indices += [a, d, c, a, c, b]
    return positions, normals, indices


def quad(width, depth):
    """An open, single quad in the XZ plane facing +Y (an open caster)."""
    hx, hz = width / 2, depth / 2
    positions = [[-hx, 0, hz], [hx, 0, hz], [hx, 0, -hz], [-hx, 0, -hz]]
    return positions, [[0, 1, 0]] * 4, [0, 1, 2, 0, 2, 3]


def png_rgba(width, height, pixels):
    """An 8-bit RGBA PNG of `pixels` (rows top first, each row width (r, g, b, a) tuples)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = bytearray()
    for row in pixels:
        raw.append(0)  # filter type None
        for texel in row:
            raw += bytes(texel)
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8 bit, RGBA, no interlace
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + \
        chunk(b"IEND", b"")


class GltfBuilder:
    def __init__(self):
        self.binary = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "tools/scripts/gltf_builder.py"},
                    "scenes": [{"name": "scene", "nodes": []}], "scene": 0, "nodes": [], "meshes": [],
                    "materials": [], "accessors": [], "bufferViews": [], "buffers": []}
        self.lights = []

    def _view(self, data, target):
        while len(self.binary) % 4:
            self.binary.append(0)
        offset = len(self.binary)
        self.binary += data
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(data), "target": target})
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind):
        if kind == "SCALAR":
            data = struct.pack("<%dI" % len(values), *values)
            view = self._view(data, 34963)
            self.doc["accessors"].append({"bufferView": view, "componentType": 5125, "count": len(values), "type": "SCALAR"})
        else:
            flat = [c for v in values for c in v]
            data = struct.pack("<%df" % len(flat), *flat)
            view = self._view(data, 34962)
            accessor = {"bufferView": view, "componentType": 5126, "count": len(values), "type": kind}
            if kind == "VEC3":
                accessor["min"] = [min(v[i] for v in values) for i in range(3)]
                accessor["max"] = [max(v[i] for v in values) for i in range(3)]
            self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def _raw_accessor(self, fmt, flat, count, kind, component_type, target=None):
        """An accessor of `count` elements of `kind` packed from `flat` with struct format
        character `fmt` (e.g. "B" unsigned byte, "f" float)."""
        view = self._view(struct.pack("<%d%s" % (len(flat), fmt), *flat), target)
        if target is None:
            del self.doc["bufferViews"][view]["target"]  # animation and skin data: no GL target
        self.doc["accessors"].append({"bufferView": view, "componentType": component_type, "count": count, "type": kind})
        return len(self.doc["accessors"]) - 1

    def skinned_mesh(self, name, geometry, material, joints, weights):
        """A mesh like mesh(), with JOINTS_0 (four joint indices per vertex, unsigned byte) and
        WEIGHTS_0 (four floats per vertex)."""
        index = self.mesh(name, geometry, material)
        attributes = self.doc["meshes"][index]["primitives"][0]["attributes"]
        attributes["JOINTS_0"] = self._raw_accessor("B", [j for v in joints for j in v], len(joints), "VEC4", 5121, 34962)
        attributes["WEIGHTS_0"] = self._accessor(weights, "VEC4")
        return index

    def skin(self, joints, inverse_bind_matrices):
        """A skin of node indices `joints` with one column-major 4x4 matrix (16 floats) each."""
        flat = [c for m in inverse_bind_matrices for c in m]
        accessor = self._raw_accessor("f", flat, len(joints), "MAT4", 5126)
        skins = self.doc.setdefault("skins", [])
        skins.append({"joints": list(joints), "inverseBindMatrices": accessor})
        return len(skins) - 1

    def rotation_animation(self, name, node, times, quaternions):
        """A LINEAR animation of `node`'s rotation through `quaternions` (x, y, z, w) at `times`."""
        inputs = self._raw_accessor("f", list(times), len(times), "SCALAR", 5126)
        self.doc["accessors"][inputs].update({"min": [min(times)], "max": [max(times)]})
        outputs = self._raw_accessor("f", [c for q in quaternions for c in q], len(quaternions), "VEC4", 5126)
        self.doc.setdefault("animations", []).append(
            {"name": name, "samplers": [{"input": inputs, "output": outputs, "interpolation": "LINEAR"}],
             "channels": [{"sampler": 0, "target": {"node": node, "path": "rotation"}}]})

    def animation(self, name, channels):
        """One animation of LINEAR channels, each (node, path, times, values): path "translation"
        (values (x, y, z)) or "rotation" (values (x, y, z, w)). Channels sharing the same times
        share one input accessor."""
        samplers, targets, inputs = [], [], {}
        for node, path, times, values in channels:
            key = tuple(times)
            if key not in inputs:
                inputs[key] = self._raw_accessor("f", list(times), len(times), "SCALAR", 5126)
                self.doc["accessors"][inputs[key]].update({"min": [min(times)], "max": [max(times)]})
            kind = {"translation": "VEC3", "rotation": "VEC4"}[path]
            outputs = self._raw_accessor("f", [c for v in values for c in v], len(values), kind, 5126)
            samplers.append({"input": inputs[key], "output": outputs, "interpolation": "LINEAR"})
            targets.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})
        self.doc.setdefault("animations", []).append({"name": name, "samplers": samplers, "channels": targets})
        return len(self.doc["animations"]) - 1

    def translation_animation(self, name, node, times, translations):
        """A LINEAR animation of `node`'s translation through `translations` (x, y, z) at `times`."""
        return self.animation(name, [(node, "translation", times, translations)])

    def parent(self, parent, children):
        """Makes nodes `children` (made by node(), light(), camera()...: scene roots) children of
        node `parent`: their transforms become relative to it, and they leave the scene's roots."""
        roots = self.doc["scenes"][0]["nodes"]
        for child in children:
            roots.remove(child)
        self.doc["nodes"][parent].setdefault("children", []).extend(children)

    def texture(self, name, png, sampler):
        """A texture of one PNG (bytes, embedded as a data URI) with a sampler (dict with
        magFilter, minFilter, wrapS, wrapT). Returns the texture's index."""
        images = self.doc.setdefault("images", [])
        images.append({"name": name, "mimeType": "image/png",
                       "uri": "data:image/png;base64," + base64.b64encode(png).decode("ascii")})
        samplers = self.doc.setdefault("samplers", [])
        samplers.append(dict(sampler))
        textures = self.doc.setdefault("textures", [])
        textures.append({"name": name, "source": len(images) - 1, "sampler": len(samplers) - 1})
        return len(textures) - 1

    def material(self, name, color, metallic=0.0, roughness=0.6, double_sided=False, base_color_texture=None,
                 alpha_mode=None, alpha_cutoff=None):
        material = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                    "metallicFactor": metallic, "roughnessFactor": roughness}}
        if base_color_texture is not None:
            material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": base_color_texture}
        if double_sided:
            material["doubleSided"] = True
        if alpha_mode is not None:
            material["alphaMode"] = alpha_mode
        if alpha_cutoff is not None:
            material["alphaCutoff"] = alpha_cutoff
        self.doc["materials"].append(material)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, geometry, material, texcoords=None):
        """`geometry` is (positions, normals, indices); `texcoords` (TEXCOORD_0, glTF's
        convention: v = 0 is the image's top row) one per position, or None."""
        positions, normals, indices = geometry
        attributes = {"POSITION": self._accessor(positions, "VEC3"), "NORMAL": self._accessor(normals, "VEC3")}
        if texcoords is not None:
            assert len(texcoords) == len(positions)
            attributes["TEXCOORD_0"] = self._accessor(texcoords, "VEC2")
        primitive = {"attributes": attributes, "indices": self._accessor(indices, "SCALAR"), "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, translation=None, rotation=None, scale=None, extras=None, **refs):
        node = {"name": name}
        if translation is not None:
            node["translation"] = list(translation)
        if rotation is not None:
            node["rotation"] = list(rotation)
        if scale is not None:
            node["scale"] = list(scale)
        if extras:
            node["extras"] = extras
        node.update(refs)
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def box_node(self, name, lo, hi, material):
        """A node holding an axis-aligned box from corner lo to corner hi (world units)."""
        size = [h - l for l, h in zip(lo, hi)]
        centre = [(l + h) / 2 for l, h in zip(lo, hi)]
        return self.node(name, translation=centre, mesh=self.mesh(name, box(size), material))

    def camera(self, name, eye, target, yfov, znear, zfar=None):
        camera = {"type": "perspective", "name": name, "perspective": {"yfov": yfov, "znear": znear}}
        if zfar:
            camera["perspective"]["zfar"] = zfar
        self.doc.setdefault("cameras", []).append(camera)
        return self.node(name, translation=eye, rotation=look_rotation(eye, target),
                         camera=len(self.doc["cameras"]) - 1)

    def light(self, name, kind, eye, target, color, intensity, shadow=None, range_=None, inner=None, outer=None):
        light = {"name": name, "type": kind, "color": list(color), "intensity": intensity}
        if range_:
            light["range"] = range_
        if kind == "spot":
            light["spot"] = {"innerConeAngle": inner, "outerConeAngle": outer}
        if shadow is not None:
            light["extras"] = {"shadow": shadow}
        self.lights.append(light)
        return self.node(name, translation=eye, rotation=look_rotation(eye, target),
                         extensions={"KHR_lights_punctual": {"light": len(self.lights) - 1}})

    def write(self, gltf_path, bin_name):
        self.doc["buffers"] = [{"uri": bin_name, "byteLength": len(self.binary)}]
        if self.lights:
            self.doc["extensionsUsed"] = ["KHR_lights_punctual"]
            self.doc["extensions"] = {"KHR_lights_punctual": {"lights": self.lights}}
        with open(gltf_path, "w") as out:
            json.dump(self.doc, out, indent=1)
            out.write("\n")
        with open(gltf_path.rsplit("/", 1)[0] + "/" + bin_name, "wb") as out:
            out.write(self.binary)
