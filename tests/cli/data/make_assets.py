#!/usr/bin/env python3
"""Writes the CLI tests' input files into this folder (run it from anywhere;
the outputs are committed, so this only reruns when the assets change):

  checker.png           8x8 texture, one color per quadrant (top-left red,
                        top-right green, bottom-left blue, bottom-right yellow)
                        so a flipped or mirrored mapping shows
  textured.gltf         two textured quads (one through KHR_texture_transform),
                        one mesh with vertex colors placed by two nodes (a
                        shared group), a camera and a directional light;
                        buffer embedded as a data URI, texture beside it
  textured.glb          the same scene as one binary file (texture inside)
  cube.obj, cube.mtl    a cube of quads: a textured front, orange elsewhere
  plane.gltf            a 2x2 quad at z = 0 facing +z, for the depth test
  expected-depth-32.pfm the depth a 32x32 view of plane.gltf from (0, 0, 3)
                        with fovy 30 degrees must give, computed analytically
  bad inputs            corrupt.gltf, truncated.glb, bad-accessor.gltf,
                        missing-buffer.gltf, cycle.gltf, bad-index.obj,
                        garbage.obj, tiny_4x4x4_uint8.raw,
                        truncated_8x8x8_uint16.raw, volume.raw
  glTF indices          mesh-index-2pow32.gltf (a node's mesh 2^32, which
                        tinygltf's int cast turned into mesh 0),
                        scene-past-end.gltf ("scene": 5 of 1),
                        material-index-2pow32.glb (a primitive's material
                        2^32 + 1 inside a GLB's JSON chunk),
                        huge-zero-accessor.gltf (POSITION without a buffer
                        view claiming 2^28 - 1 elements: nothing backs them)
  OBJ numbers           nonfinite.obj (nan, inf and 1e39 vertices beside a
                        good quad), huge-index.obj (vertex 2^63),
                        wrapping-index.obj (vertex 2^32 + 1, which a 32-bit
                        atoi reads as 1)
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(HERE, name), mode) as f:
        f.write(data)


def png_rgba(width, height, rows):
    """rows: top row first, each a list of (r, g, b, a) bytes."""
    def chunk(kind, payload):
        body = kind + payload
        return (struct.pack(">I", len(payload)) + body
                + struct.pack(">I", zlib.crc32(body) & 0xffffffff))
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    return (b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


def checker_png():
    quadrant = {(0, 0): (220, 30, 30, 255), (1, 0): (30, 200, 60, 255),
                (0, 1): (40, 60, 220, 255), (1, 1): (240, 220, 40, 255)}
    rows = [[quadrant[(x // 4, y // 4)] for x in range(8)] for y in range(8)]
    return png_rgba(8, 8, rows)


class Buffer:
    """Accumulates binary data and the bufferViews/accessors that read it."""

    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def view(self, payload):
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.data),
                           "byteLength": len(payload)})
        self.data += payload
        return len(self.views) - 1

    def accessor(self, fmt, component_type, type_, values, normalized=False,
                 bounds=False):
        flat = [c for v in values for c in (v if isinstance(v, tuple) else (v,))]
        view = self.view(struct.pack("<%d%s" % (len(flat), fmt), *flat))
        a = {"bufferView": view, "componentType": component_type,
             "count": len(values), "type": type_}
        if normalized:
            a["normalized"] = True
        if bounds:
            n = len(values[0])
            a["min"] = [min(v[i] for v in values) for i in range(n)]
            a["max"] = [max(v[i] for v in values) for i in range(n)]
        self.accessors.append(a)
        return len(self.accessors) - 1


FLOAT, UBYTE, USHORT = 5126, 5121, 5123


def quad_accessors(buf, half=1.0):
    return {
        "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                 [(-half, -half, 0.0), (half, -half, 0.0),
                                  (half, half, 0.0), (-half, half, 0.0)],
                                 bounds=True),
        "NORMAL": buf.accessor("f", FLOAT, "VEC3", [(0.0, 0.0, 1.0)] * 4),
        # glTF texture space: v grows downwards from the image's top row.
        "TEXCOORD_0": buf.accessor("f", FLOAT, "VEC2",
                                   [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)]),
    }, buf.accessor("H", USHORT, "SCALAR", [0, 1, 2, 0, 2, 3])


def textured_scene(binary):
    buf = Buffer()
    quad, quad_indices = quad_accessors(buf)
    tetra = {
        "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                 [(0.0, 0.5, 0.0), (-0.45, -0.3, 0.3),
                                  (0.45, -0.3, 0.3), (0.0, -0.3, -0.45)],
                                 bounds=True),
        "COLOR_0": buf.accessor("B", UBYTE, "VEC4",
                                [(255, 40, 40, 255), (40, 255, 40, 255),
                                 (40, 40, 255, 255), (255, 255, 255, 255)],
                                normalized=True),
    }
    tetra_indices = buf.accessor("B", UBYTE, "SCALAR",
                                 [0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2])
    texture = checker_png()
    if binary:
        image = {"bufferView": buf.view(texture), "mimeType": "image/png"}
    else:
        image = {"uri": "checker.png"}
    s = math.sin(math.pi / 8)
    c = math.cos(math.pi / 8)
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_lights_punctual",
                           "KHR_materials_clearcoat"],
        "scene": 0,
        "scenes": [{"nodes": [0, 5, 6]}],
        "nodes": [
            {"name": "root", "children": [1, 2, 3, 4]},
            {"name": "quad", "mesh": 0, "translation": [-1.0, 0.55, 0.0],
             "scale": [0.7, 0.7, 0.7]},
            {"name": "quad with texture transform", "mesh": 2,
             "translation": [1.0, 0.55, 0.0], "scale": [0.7, 0.7, 0.7]},
            {"name": "tetra left", "mesh": 1, "translation": [-0.8, -0.75, 0.0]},
            {"name": "tetra right parent", "translation": [0.8, -0.75, 0.0],
             "children": [7]},
            {"name": "camera", "camera": 0, "translation": [0.0, 0.0, 4.0]},
            {"name": "sun", "rotation": [-0.3826834, 0.0, 0.0, 0.9238795],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "tetra right", "mesh": 1, "rotation": [0.0, s, 0.0, c]},
        ],
        "meshes": [
            {"name": "quad", "primitives": [
                {"attributes": quad, "indices": quad_indices, "material": 0}]},
            {"name": "tetra", "primitives": [
                {"attributes": tetra, "indices": tetra_indices, "material": 1}]},
            {"name": "quad 2", "primitives": [
                {"attributes": quad, "indices": quad_indices, "material": 2}]},
        ],
        "materials": [
            {"name": "checker", "pbrMetallicRoughness": {
                "baseColorTexture": {"index": 0},
                "metallicFactor": 0.0, "roughnessFactor": 0.6}},
            {"name": "vertex colors", "pbrMetallicRoughness": {
                "baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.5}},
            {"name": "tiled checker", "pbrMetallicRoughness": {
                "baseColorTexture": {"index": 0, "extensions": {
                    "KHR_texture_transform": {"scale": [2.0, 2.0]}}},
                "metallicFactor": 0.0, "roughnessFactor": 0.3},
             "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 0.5}}},
        ],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728,
                      "wrapS": 10497, "wrapT": 10497}],
        "images": [image],
        "cameras": [{"type": "perspective", "perspective": {
            "yfov": 0.7, "aspectRatio": 4.0 / 3.0, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "color": [1.0, 1.0, 1.0], "intensity": 2.0}]}},
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    data = bytes(buf.data)
    if not binary:
        gltf["buffers"] = [{"byteLength": len(data), "uri":
                            "data:application/octet-stream;base64,"
                            + base64.b64encode(data).decode()}]
        return json.dumps(gltf, indent=1)
    gltf["buffers"] = [{"byteLength": len(data)}]
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    data += b"\x00" * (-len(data) % 4)
    body = (struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(data)) + b"BIN\x00" + data)
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def plane_scene():
    buf = Buffer()
    quad, indices = quad_accessors(buf, half=2.0)
    gltf = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": quad, "indices": indices}]}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
        "buffers": [{"byteLength": len(buf.data), "uri":
                     "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(buf.data)).decode()}],
    }
    return json.dumps(gltf, indent=1)


def material_index_glb():
    """plane_scene as a GLB whose primitive names material 2^32 + 1 (of 1)."""
    buf = Buffer()
    quad, indices = quad_accessors(buf, half=2.0)
    gltf = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": quad, "indices": indices,
                                    "material": 2 ** 32 + 1}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
        "buffers": [{"byteLength": len(buf.data)}],
    }
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    data = bytes(buf.data) + b"\x00" * (-len(buf.data) % 4)
    body = (struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(data)) + b"BIN\x00" + data)
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def expected_depth(size, distance, fovy_degrees):
    """PFM (bottom row first) of the distance from a pinhole at (0, 0,
    distance) to the plane z = 0 through each pixel center."""
    t = math.tan(math.radians(fovy_degrees) / 2)
    values = []
    for y in range(size):
        for x in range(size):
            u = ((x + 0.5) / size - 0.5) * 2 * t
            v = ((y + 0.5) / size - 0.5) * 2 * t
            d = distance * math.sqrt(1 + u * u + v * v)
            values += [d, d, d]
    header = b"PF\n%d %d\n-1.0\n" % (size, size)
    return header + struct.pack("<%df" % len(values), *values)


CUBE_OBJ = """# A unit cube of quads: the front (+z) face textured, the others orange.
mtllib cube.mtl
v -0.5 -0.5  0.5
v  0.5 -0.5  0.5
v  0.5  0.5  0.5
v -0.5  0.5  0.5
v -0.5 -0.5 -0.5
v  0.5 -0.5 -0.5
v  0.5  0.5 -0.5
v -0.5  0.5 -0.5
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
vn 0 0 -1
vn 1 0 0
vn -1 0 0
vn 0 1 0
vn 0 -1 0
o cube
usemtl checker
f 1/1/1 2/2/1 3/3/1 4/4/1
usemtl orange
f 6/1/2 5/2/2 8/3/2 7/4/2
f 2/1/3 6/2/3 7/3/3 3/4/3
f 5/1/4 1/2/4 4/3/4 8/4/4
f 4/1/5 3/2/5 7/3/5 8/4/5
f 5/1/6 6/2/6 2/3/6 1/4/6
"""

CUBE_MTL = """newmtl checker
Kd 1 1 1
Ns 50
map_Kd checker.png

newmtl orange
Kd 0.9 0.45 0.1
Ns 10
"""

NONFINITE_OBJ = """# A quad that renders, and three triangles whose third vertex is not a
# finite number: they must be left out with one warning.
v -1 -1 0
v  1 -1 0
v  1  1 0
v -1  1 0
v nan 0 0
v 0 inf 0
v 0 0 1e39
f 1 2 3 4
f 1 2 5
f 2 3 6
f 3 4 7
"""


def main():
    write("checker.png", checker_png())
    write("textured.gltf", textured_scene(binary=False))
    glb = textured_scene(binary=True)
    write("textured.glb", glb)
    write("plane.gltf", plane_scene())
    write("expected-depth-32.pfm", expected_depth(32, 3.0, 30.0))
    write("cube.obj", CUBE_OBJ)
    write("cube.mtl", CUBE_MTL)

    # Bad inputs, each broken in one way.
    write("corrupt.gltf", '{"asset": {"version": "2.0"}, "meshes": [ this is not json')
    write("truncated.glb", glb[: len(glb) // 2])
    bad = json.loads(textured_scene(binary=False))
    bad["accessors"][0]["count"] = 100000  # POSITION far beyond its buffer
    write("bad-accessor.gltf", json.dumps(bad))
    missing = json.loads(plane_scene())
    missing["buffers"][0]["uri"] = "missing.bin"
    write("missing-buffer.gltf", json.dumps(missing))
    cycle = json.loads(plane_scene())
    cycle["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
    write("cycle.gltf", json.dumps(cycle))
    wrapped = json.loads(plane_scene())
    wrapped["nodes"][0]["mesh"] = 2 ** 32
    write("mesh-index-2pow32.gltf", json.dumps(wrapped))
    past_end = json.loads(plane_scene())
    past_end["scene"] = 5
    write("scene-past-end.gltf", json.dumps(past_end))
    write("material-index-2pow32.glb", material_index_glb())
    zeros = json.loads(plane_scene())
    del zeros["accessors"][0]["bufferView"]
    zeros["accessors"][0]["count"] = 2 ** 28 - 1
    write("huge-zero-accessor.gltf", json.dumps(zeros))
    write("bad-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    write("garbage.obj", bytes((i * 37 + 11) % 256 for i in range(512)))
    write("nonfinite.obj", NONFINITE_OBJ)
    write("huge-index.obj",
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775808\n")
    write("wrapping-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n")
    write("tiny_4x4x4_uint8.raw", bytes(range(64)))
    write("truncated_8x8x8_uint16.raw", bytes(1000))
    write("volume.raw", bytes(64))


if __name__ == "__main__":
    main()
