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
                        truncated_8x8x8_uint16.raw, volume.raw,
                        overflow_999999999x999999999x999999999_uint8.raw
  glTF indices          mesh-index-2pow32.gltf (a node's mesh 2^32, which
                        tinygltf's int cast turned into mesh 0),
                        scene-past-end.gltf ("scene": 5 of 1),
                        material-index-2pow32.glb (a primitive's material
                        2^32 + 1 inside a GLB's JSON chunk),
                        huge-zero-accessor.gltf (POSITION without a buffer
                        view claiming 2^28 - 1 elements: nothing backs them),
                        missing-texture.gltf (its PNG does not exist)
  default lighting      lightless-box.gltf (a textured box, no lights: lit by
                        the tool's studio by default, black with --env
                        none), lit-box.gltf (the box under a directional
                        light along -z), emissive-box.gltf (an emissive box,
                        no lights), emissive-label.gltf (a grey box with a
                        green-emitting label, no lights),
                        red-sky.hdr (8x4, radiance (1, 0, 0)
                        everywhere), glowing.obj/.mtl (a quad with Ke),
                        named-normals.obj (a quad whose faces name vn and
                        vt the file does not have)
  instancing            instanced-grid.gltf: one quad placed six times by
                        EXT_mesh_gpu_instancing (INSTANCE_GRID)
  framing               sphere.obj: a unit UV sphere (framed on its
                        silhouette, not its bounding box)
  variants              variants.gltf: a quad, red by default, "green" and
                        "blue" as KHR_materials_variants
  morph targets         morphed-quad.gltf: a quad moved to z = 0.5 by its
                        default morph weights
  skins                 skinned-bar.gltf: a bar bent by 90 degrees by its
                        second joint; animated-bar.gltf: the same joint
                        turning from 0 (t = 0) to 90 degrees (t = 2)
  normal maps           normal-mapped-plane.gltf: a plane of two UV islands,
                        the right one mirrored in TEXCOORD_1 (which the
                        normal map reads; TEXCOORD_0 is a plain planar map),
                        no TANGENT, lit by a directional light from the
                        upper right; -tangents.gltf: the same with the
                        analytic TANGENT (left (1, 0, 0, -1), right
                        (-1, 0, 0, 1)); -unmirrored.gltf: the right island's
                        TANGENT wrong on purpose (as if not mirrored)
  Fresnel               fresnel-plane.gltf: a 200x200 smooth black dielectric
                        plane (no material extensions) seen from 1 unit above
                        at 20 degrees down (yfov 0.5); white-sky.hdr (8x4,
                        radiance 1 everywhere); expected-fresnel-48.pfm: the
                        glTF BRDF's answer for a 48x48 view, Schlick's
                        F = 0.04 + 0.96 (1 - cos)^5 of each ray averaged over
                        its pixel (the reflection sees the sky, 1)
  material extensions   unlit.gltf (a checker quad, KHR_materials_unlit, under a
                        strong light), vertex-color-texture.gltf (the checker
                        times COLOR_0 (0.5, 1, 0.25)), spec-gloss.gltf (four
                        KHR_materials_pbrSpecularGlossiness quads: chrome,
                        black plastic (specular 0.04), a colored dielectric
                        and a textured one), single-sided.gltf (two quads
                        turned away from the camera, the left single-sided),
                        expected-*.pfm for each: what an exact answer gives
                        (linear texel colors, products, the published
                        specular-glossiness conversion); all seen through an
                        orthographic camera that the quads fill exactly
  points and lines      points-lines.gltf: one mesh under a node scaled by 2
                        (positions halved) of POINTS (red, green and blue at
                        x = -0.1, 0, 0.1 and a white one far off at (5, 5):
                        the scene's diagonal is 7.23, so curves get radius
                        0.00723 and spheres 3 times that), a LINE_STRIP
                        (yellow, y = -0.1),
                        LINES (magenta, x = 0.12) and a LINE_LOOP (a cyan
                        square whose closing edge is its left side), seen
                        by an orthographic camera over [-0.15, 0.15]^2
  volume attenuation    attenuation-slabs.gltf: two smooth transmissive boxes 2
                        deep along an orthographic view, attenuationColor
                        (0.5, 0.25, 0.8) at attenuationDistance 1, the left
                        of ior 1, the right of ior 1.5
  negative scale        mirrored-quads.gltf: single-sided quads under a node of
                        scale (-1, 1, 1), one facing the camera, one turned
                        away, and a receiver behind a quad whose front
                        faces it, under a directional light along -z
  iridescent glass      iridescent-glass.gltf: a smooth single-sided glass box
                        with an iridescent film, filling an orthographic view
  anisotropy            anisotropic-plates.gltf: two brushed white metal plates
                        (KHR_materials_anisotropy strength 0.8, the right
                        turned by 90 degrees), each under a point light,
                        seen from above; -no-tangents.gltf: the same
                        without TANGENT, u along +y: tangents generated
                        from it run along y, so the highlights turn
  unsupported           draco-*.gltf (KHR_draco_mesh_compression), basisu-*.gltf
  extensions            (KHR_texture_basisu; the KTX2 image is only the magic
                        number), meshopt-*.gltf (EXT_meshopt_compression):
                        -required (in extensionsRequired), -no-fallback (only
                        used, but a primitive or texture depends on it),
                        -fallback (only used, with the uncompressed data or
                        a PNG: renders)
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


def data_uri(kind, payload):
    return "data:%s;base64,%s" % (kind, base64.b64encode(payload).decode())


def finish_gltf(gltf, buf):
    """Adds the buffer (as a data URI), views and accessors; JSON text."""
    gltf["bufferViews"] = buf.views
    gltf["accessors"] = buf.accessors
    gltf["buffers"] = [{"byteLength": len(buf.data),
                        "uri": data_uri("application/octet-stream",
                                        bytes(buf.data))}]
    return json.dumps(gltf, indent=1)


# The faces of an axis-aligned cube: (normal, u axis, v axis); v grows down
# the image in glTF, so the v axis points down each face.
CUBE_FACES = [((0, 0, 1), (1, 0, 0), (0, -1, 0)),
              ((0, 0, -1), (-1, 0, 0), (0, -1, 0)),
              ((1, 0, 0), (0, 0, -1), (0, -1, 0)),
              ((-1, 0, 0), (0, 0, 1), (0, -1, 0)),
              ((0, 1, 0), (1, 0, 0), (0, 0, 1)),
              ((0, -1, 0), (1, 0, 0), (0, 0, -1))]


def cube_primitive(buf, half=0.5):
    """A cube of 24 vertices (normals and uvs per face), 12 triangles."""
    positions, normals, uvs, indices = [], [], [], []
    for n, u, v in CUBE_FACES:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            positions.append(tuple(half * (n[i] + su * u[i] + sv * v[i])
                                   for i in range(3)))
            normals.append(tuple(float(c) for c in n))
            uvs.append(((su + 1) / 2.0, (sv + 1) / 2.0))
        # (u, v) with v pointing down the face is clockwise seen from
        # outside, so the corners go 0, 3, 2 / 0, 2, 1 to face out.
        indices += [base, base + 3, base + 2, base, base + 2, base + 1]
    return {"attributes": {
        "POSITION": buf.accessor("f", FLOAT, "VEC3", positions, bounds=True),
        "NORMAL": buf.accessor("f", FLOAT, "VEC3", normals),
        "TEXCOORD_0": buf.accessor("f", FLOAT, "VEC2", uvs)},
        "indices": buf.accessor("H", USHORT, "SCALAR", indices)}


def box_scene(kind):
    """The lighting tests' box: 'lightless' (textured, nothing emits),
    'lit' (plus a directional light shining along -z) or 'emissive'."""
    buf = Buffer()
    primitive = cube_primitive(buf)
    primitive["material"] = 0
    material = {"pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0},
        "metallicFactor": 0.0, "roughnessFactor": 0.6}}
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "box", "mesh": 0}],
        "meshes": [{"primitives": [primitive]}],
        "materials": [material],
        "textures": [{"source": 0}],
        "images": [{"uri": data_uri("image/png", checker_png())}],
    }
    if kind == "lit":
        gltf["extensionsUsed"] = ["KHR_lights_punctual"]
        gltf["scenes"][0]["nodes"].append(1)
        # A light node's default direction is -z.
        gltf["nodes"].append({"name": "light",
                              "extensions": {"KHR_lights_punctual": {"light": 0}}})
        gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": 3.0}]}}
    elif kind == "emissive":
        material["emissiveFactor"] = [1.0, 0.5, 0.2]
    return finish_gltf(gltf, buf)


def rgbe(r, g, b):
    """One Radiance RGBE pixel (shared exponent)."""
    top = max(r, g, b)
    if top < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(top)
    scale = mantissa * 256.0 / top
    return bytes((int(r * scale), int(g * scale), int(b * scale),
                  exponent + 128))


def uniform_hdr(width, height, rgb):
    """A Radiance .hdr (flat, not run-length encoded) of one radiance."""
    header = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (
        height, width)
    return header + rgbe(*rgb) * (width * height)


GLOWING_OBJ = """# A quad whose material emits (Ke): the scene lights itself.
mtllib glowing.mtl
v -1 -1 0
v  1 -1 0
v  1  1 0
v -1  1 0
usemtl glow
f 1 2 3 4
"""

# A quad whose faces name normals and texture coordinates the file never
# wrote, as some exporters do: rendered without them, with a note.
NAMED_NORMALS_OBJ = """v -1 -1 0
v  1 -1 0
v  1  1 0
v -1  1 0
f 1/1/1 2/2/2 3/3/3 4/4/4
"""

def uv_sphere_obj(rings=12, segments=24):
    """A unit sphere of quads (triangles at the poles), no normals: framing
    must fit its silhouette, not its bounding box."""
    lines = ["# A unit UV sphere, %d rings of %d segments" % (rings, segments),
             "v 0 1 0"]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            lines.append("v %.6f %.6f %.6f" % (math.sin(theta) * math.cos(phi),
                                               math.cos(theta),
                                               math.sin(theta) * math.sin(phi)))
    lines.append("v 0 -1 0")
    bottom = 2 + (rings - 1) * segments

    def ring(r, s):  # 1-based index of ring r (1..rings-1), segment s
        return 2 + (r - 1) * segments + s % segments

    for s in range(segments):
        lines.append("f 1 %d %d" % (ring(1, s + 1), ring(1, s)))
        lines.append("f %d %d %d" % (bottom, ring(rings - 1, s),
                                     ring(rings - 1, s + 1)))
        for r in range(1, rings - 1):
            lines.append("f %d %d %d %d" % (ring(r, s), ring(r, s + 1),
                                            ring(r + 1, s + 1),
                                            ring(r + 1, s)))
    return "\n".join(lines) + "\n"


GLOWING_MTL = """newmtl glow
Kd 0.5 0.5 0.5
Ke 2 1 0.5
"""


def normal_png(nx, ny, nz):
    """A 4x4 tangent-space normal map of one normal (n * 0.5 + 0.5)."""
    texel = tuple(int(round((c * 0.5 + 0.5) * 255)) for c in (nx, ny, nz)) + (255,)
    return png_rgba(4, 4, [[texel] * 4 for _ in range(4)])


def normal_mapped_plane(tangents):
    """A 2x2 plane at z = 0 facing +z of two quads (UV islands). TEXCOORD_1
    runs u along +x on the left island and along -x on the right (mirrored),
    v down (-y) on both; the normal map reads TEXCOORD_1. `tangents`: None,
    'analytic' (what a correct generator must give: T along increasing u, w
    such that cross(N, T) * w runs along decreasing v, up the image, where
    glTF's normal maps point +Y; MikkTSpace as glTF exporters run it) or
    'unmirrored' (the right island's tangent as if it were not mirrored)."""
    buf = Buffer()
    positions, uv0, uv1, tangent = [], [], [], []
    for island, (x0, x1) in enumerate(((-1.0, 0.0), (0.0, 1.0))):
        for x, y in ((x0, -1.0), (x1, -1.0), (x1, 1.0), (x0, 1.0)):
            positions.append((x, y, 0.0))
            uv0.append(((x + 1) / 2, (1 - y) / 2))
            u = x + 1 if island == 0 else 1 - x
            uv1.append((u, (1 - y) / 2))
            if island == 0 or tangents == "unmirrored":
                tangent.append((1.0, 0.0, 0.0, 1.0))
            else:
                tangent.append((-1.0, 0.0, 0.0, -1.0))
    attributes = {
        "POSITION": buf.accessor("f", FLOAT, "VEC3", positions, bounds=True),
        "NORMAL": buf.accessor("f", FLOAT, "VEC3", [(0.0, 0.0, 1.0)] * 8),
        "TEXCOORD_0": buf.accessor("f", FLOAT, "VEC2", uv0),
        "TEXCOORD_1": buf.accessor("f", FLOAT, "VEC2", uv1)}
    if tangents:
        attributes["TANGENT"] = buf.accessor("f", FLOAT, "VEC4", tangent)
    indices = buf.accessor("H", USHORT, "SCALAR",
                           [0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7])
    # A normal tilted towards +u and +v (0.48, 0.36, 0.8): each island
    # leans its own way, so a wrong tangent or sign shows.
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0.0, 0.0, 3.0]},
                  {"rotation": [-0.2126, 0.3172, 0.0735, 0.9212],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "meshes": [{"primitives": [{"attributes": attributes,
                                    "indices": indices, "material": 0}]}],
        "materials": [{"normalTexture": {"index": 0, "texCoord": 1},
                       "pbrMetallicRoughness": {"metallicFactor": 0.0,
                                                "roughnessFactor": 0.7}}],
        "textures": [{"source": 0}],
        "images": [{"uri": data_uri("image/png", normal_png(0.48, 0.36, 0.8))}],
        "cameras": [{"type": "perspective", "perspective": {
            "yfov": 0.8, "aspectRatio": 1.0, "znear": 0.1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": 2.0}]}},
    }
    return finish_gltf(gltf, buf)


FRESNEL_PITCH = math.radians(20.0)  # camera looks this far below the horizon
FRESNEL_YFOV = 0.5


def fresnel_plane():
    buf = Buffer()
    half = 100.0
    attributes = {
        "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                 [(-half, 0.0, half), (half, 0.0, half),
                                  (half, 0.0, -half), (-half, 0.0, -half)],
                                 bounds=True),
        "NORMAL": buf.accessor("f", FLOAT, "VEC3", [(0.0, 1.0, 0.0)] * 4)}
    indices = buf.accessor("H", USHORT, "SCALAR", [0, 1, 2, 0, 2, 3])
    a = -FRESNEL_PITCH / 2
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0.0, 1.0, 0.0],
                   "rotation": [math.sin(a), 0.0, 0.0, math.cos(a)]}],
        "meshes": [{"primitives": [{"attributes": attributes,
                                    "indices": indices, "material": 0}]}],
        # A plain glTF dielectric: black, smooth, no extensions.
        "materials": [{"pbrMetallicRoughness": {
            "baseColorFactor": [0.0, 0.0, 0.0, 1.0],
            "metallicFactor": 0.0, "roughnessFactor": 0.0}}],
        "cameras": [{"type": "perspective", "perspective": {
            "yfov": FRESNEL_YFOV, "aspectRatio": 1.0, "znear": 0.01}}],
    }
    return finish_gltf(gltf, buf)


def expected_fresnel(size, subsamples=16):
    """What the glTF BRDF gives fresnel_plane() under a sky of radiance 1:
    a smooth dielectric (ior 1.5, specular 1) reflects Schlick's
    F = 0.04 + 0.96 (1 - cos)^5 of the sky, cos between the ray and the
    normal; each pixel the mean over a subsamples^2 grid. PFM, bottom row
    first."""
    t = math.tan(FRESNEL_YFOV / 2)
    forward = (0.0, -math.sin(FRESNEL_PITCH), -math.cos(FRESNEL_PITCH))
    up = (0.0, math.cos(FRESNEL_PITCH), -math.sin(FRESNEL_PITCH))
    right = (1.0, 0.0, 0.0)
    rows = []
    for y in range(size):  # y = 0 is the bottom row
        row = []
        for x in range(size):
            total = 0.0
            for sy in range(subsamples):
                for sx in range(subsamples):
                    u = ((x + (sx + 0.5) / subsamples) / size - 0.5) * 2 * t
                    v = ((y + (sy + 0.5) / subsamples) / size - 0.5) * 2 * t
                    d = [forward[i] + u * right[i] + v * up[i] for i in range(3)]
                    cos = -d[1] / math.sqrt(sum(c * c for c in d))
                    total += 0.04 + 0.96 * (1.0 - cos) ** 5
            f = total / subsamples ** 2
            row += [f, f, f]
        rows += row
    header = b"PF\n%d %d\n-1.0\n" % (size, size)
    return header + struct.pack("<%df" % len(rows), *rows)


def linear(c8):
    """An 8-bit sRGB value as linear."""
    c = c8 / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


CHECKER_QUADRANTS = {(0, 0): (220, 30, 30), (1, 0): (30, 200, 60),
                     (0, 1): (40, 60, 220), (1, 1): (240, 220, 40)}


def checker_linear(u, v):
    """checker.png's linear color at texture coordinates (u, v), v down."""
    c = CHECKER_QUADRANTS[(min(int(u * 2), 1), min(int(v * 2), 1))]
    return tuple(linear(x) for x in c)


# EXT_mesh_gpu_instancing: one white quad (half size 0.1) placed six times
# in a 3 x 2 grid at x = -0.5, 0, 0.5 and y = 0.25, -0.25, seen by an
# orthographic camera over [-1, 1]^2; the middle of the lower row is scaled
# by 2 and its right neighbour turned 45 degrees about z.
INSTANCE_GRID = [((-0.5, 0.25), 1.0, 0.0), ((0.0, 0.25), 1.0, 0.0),
                 ((0.5, 0.25), 1.0, 0.0), ((-0.5, -0.25), 1.0, 0.0),
                 ((0.0, -0.25), 2.0, 0.0), ((0.5, -0.25), 1.0, 45.0)]


def instanced_grid():
    buf = Buffer()
    attributes, indices = quad_accessors(buf, half=0.1)
    translations = [(x, y, 0.0) for (x, y), _, _ in INSTANCE_GRID]
    rotations = [(0.0, 0.0, math.sin(math.radians(a) / 2),
                  math.cos(math.radians(a) / 2)) for _, _, a in INSTANCE_GRID]
    scales = [(s, s, 1.0) for _, s, _ in INSTANCE_GRID]
    gltf = {
        "asset": {"version": "2.0",
                  "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {
            "attributes": {
                "TRANSLATION": buf.accessor("f", FLOAT, "VEC3", translations),
                "ROTATION": buf.accessor("f", FLOAT, "VEC4", rotations),
                "SCALE": buf.accessor("f", FLOAT, "VEC3", scales)}}}},
            {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"primitives": [{"attributes": attributes,
                                    "indices": indices, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0}}],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


def variants_quad():
    """KHR_materials_variants: a quad filling an orthographic view, red by
    default, green in the variant "green" and blue in "blue"."""
    buf = Buffer()
    attributes, indices = quad_accessors(buf)

    def colored(rgb):
        return {"pbrMetallicRoughness": {"baseColorFactor": list(rgb) + [1.0],
                                         "metallicFactor": 0.0}}

    gltf = {
        "asset": {"version": "2.0",
                  "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_materials_variants"],
        "extensions": {"KHR_materials_variants": {
            "variants": [{"name": "green"}, {"name": "blue"}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"primitives": [{
            "attributes": attributes, "indices": indices, "material": 0,
            "extensions": {"KHR_materials_variants": {"mappings": [
                {"material": 1, "variants": [0]},
                {"material": 2, "variants": [1]}]}}}]}],
        "materials": [colored((1.0, 0.0, 0.0)), colored((0.0, 1.0, 0.0)),
                      colored((0.0, 0.0, 1.0))],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


def morphed_quad():
    """A quad filling an orthographic view from z = 3, at z = 0, with two
    morph targets: +1 along z (mesh weight 0.5: the quad renders at z = 0.5,
    depth 2.5) and +10 along x (weight 0: no effect)."""
    buf = Buffer()
    attributes, indices = quad_accessors(buf)
    gltf = {
        "asset": {"version": "2.0",
                  "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"weights": [0.5, 0.0], "primitives": [{
            "attributes": attributes, "indices": indices,
            "targets": [
                {"POSITION": buf.accessor("f", FLOAT, "VEC3",
                                          [(0.0, 0.0, 1.0)] * 4)},
                {"POSITION": buf.accessor("f", FLOAT, "VEC3",
                                          [(10.0, 0.0, 0.0)] * 4)}]}]}],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


def animated_bar():
    """skinned_bar() with its second joint animated: turned 0 degrees at
    t = 0 and 90 at t = 2 (LINEAR: 45 at t = 1)."""
    gltf = json.loads(skinned_bar())
    buf = Buffer()
    buf.data = bytearray(base64.b64decode(
        gltf["buffers"][0]["uri"].split(",", 1)[1]))
    buf.views, buf.accessors = gltf["bufferViews"], gltf["accessors"]
    half = math.sqrt(0.5)
    gltf["animations"] = [{
        "samplers": [{
            "input": buf.accessor("f", FLOAT, "SCALAR", [(0.0,), (2.0,)],
                                  bounds=True),
            "output": buf.accessor("f", FLOAT, "VEC4",
                                   [(0.0, 0.0, 0.0, 1.0),
                                    (0.0, 0.0, half, half)]),
            "interpolation": "LINEAR"}],
        "channels": [{"sampler": 0,
                      "target": {"node": 2, "path": "rotation"}}]}]
    return finish_gltf(gltf, buf)


def skinned_bar():
    """A bar 0.2 wide from x = 0 to 2 along y = 0, skinned to two joints:
    the root at the origin holds x = 0 and 1, the second (a child at x = 1,
    turned 90 degrees about z) holds x = 2, so the posed bar runs right to
    (1, 0), then up to (1, 1). The mesh node's own translation (5, 0, 0)
    does not apply to a skinned mesh. An orthographic camera sees x in
    [0, 2], y in [-0.5, 1.5]."""
    buf = Buffer()
    positions = [(x, y, 0.0) for x in (0.0, 1.0, 2.0) for y in (-0.1, 0.1)]
    indices = [0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3]
    joints = [(0, 0, 0, 0)] * 4 + [(1, 0, 0, 0)] * 2
    weights = [(1.0, 0.0, 0.0, 0.0)] * 6
    inverse_bind = [(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                     0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0),
                    (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                     0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0)]
    half = math.sqrt(0.5)
    gltf = {
        "asset": {"version": "2.0",
                  "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 3]}],
        "nodes": [{"mesh": 0, "skin": 0, "translation": [5.0, 0.0, 0.0]},
                  {"children": [2]},
                  {"translation": [1.0, 0.0, 0.0],
                   "rotation": [0.0, 0.0, half, half]},
                  {"camera": 0, "translation": [1.0, 0.5, 3.0]}],
        "skins": [{"joints": [1, 2], "inverseBindMatrices":
                   buf.accessor("f", FLOAT, "MAT4", inverse_bind)}],
        "meshes": [{"primitives": [{
            "attributes": {
                "POSITION": buf.accessor("f", FLOAT, "VEC3", positions,
                                         bounds=True),
                "JOINTS_0": buf.accessor("B", UBYTE, "VEC4", joints),
                "WEIGHTS_0": buf.accessor("f", FLOAT, "VEC4", weights)},
            "indices": buf.accessor("H", USHORT, "SCALAR", indices),
            "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"metallicFactor": 0.0}}],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


def quads_gltf(quads, materials, images=None, extensions_used=None,
               lights=False, view_half=1.0):
    """Unit-textured 2 * half squares at z = 0, each (cx, cy, half, material,
    facing_camera, color or None), seen by an orthographic camera at z = 3
    whose view (2 * view_half square) they fill."""
    buf = Buffer()
    primitives = []
    for cx, cy, half, material, facing, color in quads:
        corners = [(cx - half, cy - half), (cx + half, cy - half),
                   (cx + half, cy + half), (cx - half, cy + half)]
        attributes = {
            "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                     [(x, y, 0.0) for x, y in corners],
                                     bounds=True),
            "NORMAL": buf.accessor("f", FLOAT, "VEC3",
                                   [(0.0, 0.0, 1.0 if facing else -1.0)] * 4),
            "TEXCOORD_0": buf.accessor("f", FLOAT, "VEC2",
                                       [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0),
                                        (0.0, 0.0)])}
        if color:
            attributes["COLOR_0"] = buf.accessor("f", FLOAT, "VEC4",
                                                 [color] * 4)
        order = [0, 1, 2, 0, 2, 3] if facing else [0, 2, 1, 0, 3, 2]
        primitives.append({"attributes": attributes, "material": material,
                           "indices": buf.accessor("H", USHORT, "SCALAR", order)})
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"primitives": primitives}],
        "materials": materials,
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": view_half, "ymag": view_half, "znear": 0.1, "zfar": 10.0}}],
    }
    if images:
        gltf["images"] = [{"uri": data_uri("image/png", png)} for png in images]
        gltf["textures"] = [{"source": i, "sampler": 0}
                            for i in range(len(images))]
        gltf["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    if extensions_used:
        gltf["extensionsUsed"] = list(extensions_used)
    if lights:
        gltf.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
        gltf["scenes"][0]["nodes"].append(2)
        gltf["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
        gltf["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": 10.0}]}}
    return finish_gltf(gltf, buf)


def expected_image(size, view_half, color_at):
    """PFM (bottom row first) of color_at(x, y) at each pixel centre, in
    world units on the z = 0 plane the orthographic camera sees."""
    values = []
    for row in range(size):
        for col in range(size):
            x = ((col + 0.5) / size * 2 - 1) * view_half
            y = ((row + 0.5) / size * 2 - 1) * view_half
            values += list(color_at(x, y))
    header = b"PF\n%d %d\n-1.0\n" % (size, size)
    return header + struct.pack("<%df" % len(values), *values)


def unlit_files():
    material = {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                         "metallicFactor": 0.0},
                "extensions": {"KHR_materials_unlit": {}}}
    scene = quads_gltf([(0, 0, 1, 0, True, None)], [material],
                       images=[checker_png()],
                       extensions_used=["KHR_materials_unlit"], lights=True)
    expected = expected_image(32, 1.0, lambda x, y: checker_linear(
        (x + 1) / 2, (1 - y) / 2))
    return scene, expected


VERTEX_COLOR = (0.5, 1.0, 0.25, 1.0)


def vertex_color_files():
    material = {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                         "metallicFactor": 0.0}}
    scene = quads_gltf([(0, 0, 1, 0, True, VERTEX_COLOR)], [material],
                       images=[checker_png()])
    expected = expected_image(32, 1.0, lambda x, y: tuple(
        c * k for c, k in zip(checker_linear((x + 1) / 2, (1 - y) / 2),
                              VERTEX_COLOR)))
    return scene, expected


def spec_gloss_base(diffuse, specular, glossiness):
    """The published specular-glossiness to metallic-roughness conversion
    (linear colors): (base rgb, metallic, roughness)."""
    def brightness(c):
        return math.sqrt(0.299 * c[0] ** 2 + 0.587 * c[1] ** 2
                         + 0.114 * c[2] ** 2)
    d, sp = brightness(diffuse), brightness(specular)
    one_minus = 1 - max(specular)
    metallic = 0.0
    if sp >= 0.04:
        a, b, c = 0.04, d * one_minus / 0.96 + sp - 0.08, 0.04 - sp
        metallic = min(max((-b + math.sqrt(max(b * b - 4 * a * c, 0))) / (2 * a),
                           0.0), 1.0)
    base = []
    for i in range(3):
        from_diffuse = diffuse[i] * one_minus / 0.96 / max(1 - metallic, 1e-6)
        from_specular = (specular[i] - 0.04 * (1 - metallic)) / max(metallic, 1e-6)
        t = metallic * metallic
        base.append(min(max(from_diffuse + (from_specular - from_diffuse) * t,
                            0.0), 1.0))
    return tuple(base), metallic, 1 - glossiness


SPEC_GLOSS = [  # (cx, cy, diffuse, specular, glossiness, textured)
    (-1, 1, (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 1.0, False),   # chrome
    (1, 1, (0.0, 0.0, 0.0), (0.04, 0.04, 0.04), 1.0, False),  # black plastic
    (-1, -1, (0.5, 0.25, 0.1), (0.04, 0.04, 0.04), 0.5, False),
    (1, -1, (1.0, 1.0, 1.0), (1.0, 1.0, 1.0), 1.0, True),     # textured
]


def spec_gloss_files():
    # The textured quad: diffuse checker.png; specular-glossiness a 2x2
    # image of black specular (sRGB 0) and glossiness 1.
    black_glossy = png_rgba(2, 2, [[(0, 0, 0, 255)] * 2] * 2)
    materials, quads = [], []
    for i, (cx, cy, diffuse, specular, gloss, textured) in enumerate(SPEC_GLOSS):
        ext = {"diffuseFactor": list(diffuse) + [1.0],
               "specularFactor": list(specular), "glossinessFactor": gloss}
        if textured:
            ext["diffuseTexture"] = {"index": 0}
            ext["specularGlossinessTexture"] = {"index": 1}
        materials.append({"extensions": {
            "KHR_materials_pbrSpecularGlossiness": ext}})
        quads.append((cx, cy, 1, i, True, None))
    scene = quads_gltf(quads, materials, images=[checker_png(), black_glossy],
                       extensions_used=["KHR_materials_pbrSpecularGlossiness"],
                       view_half=2.0)

    def base_at(x, y):
        for cx, cy, diffuse, specular, gloss, textured in SPEC_GLOSS:
            if abs(x - cx) < 1 and abs(y - cy) < 1:
                if textured:
                    diffuse = checker_linear((x - cx + 1) / 2, (cy + 1 - y) / 2)
                    specular = (0.0, 0.0, 0.0)
                return spec_gloss_base(diffuse, specular, gloss)[0]
        return (0.0, 0.0, 0.0)
    return scene, expected_image(32, 2.0, base_at)


def single_sided_file():
    red = {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1.0],
                                    "metallicFactor": 0.0}}
    both = dict(red, doubleSided=True)
    # Both turned away from the camera: the left (single-sided, glTF's
    # default) is invisible, the right (doubleSided) shows its back.
    return quads_gltf([(-1, 0, 1, 0, False, None), (1, 0, 1, 1, False, None)],
                      [red, both], view_half=2.0)


def points_lines_file():
    buf = Buffer()

    def primitive(mode, points, material, colors=None):
        # The node scales by 2: positions are stored halved.
        attributes = {"POSITION": buf.accessor(
            "f", FLOAT, "VEC3", [(x / 2, y / 2, 0.0) for x, y in points],
            bounds=True)}
        if colors:
            attributes["COLOR_0"] = buf.accessor("f", FLOAT, "VEC3", colors)
        return {"attributes": attributes, "mode": mode, "material": material}
    primitives = [
        primitive(0, [(-0.1, 0.0), (0.0, 0.0), (0.1, 0.0), (5.0, 5.0)], 0,
                  [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0),
                   (1.0, 1.0, 1.0)]),
        primitive(3, [(-0.1, -0.1), (0.0, -0.1), (0.1, -0.1)], 1),
        primitive(1, [(0.12, 0.05), (0.12, 0.12)], 2),
        primitive(2, [(-0.12, 0.06), (-0.06, 0.06), (-0.06, 0.12),
                      (-0.12, 0.12)], 3),
    ]

    def flat(r, g, b):
        return {"pbrMetallicRoughness": {"baseColorFactor": [r, g, b, 1.0],
                                         "metallicFactor": 0.0},
                "doubleSided": True}
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "scale": [2.0, 2.0, 2.0]},
                  {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"primitives": primitives}],
        "materials": [flat(1, 1, 1), flat(1, 1, 0), flat(1, 0, 1),
                      flat(0, 1, 1)],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 0.15, "ymag": 0.15, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


# The attenuation slabs: attenuationColor, over attenuationDistance 1, and
# the slabs' depth 2 along the view (world units, the node's z scale).
SLAB_COLOR = (0.5, 0.25, 0.8)


def attenuation_slabs():
    """Two smooth transmissive boxes 2 deep along the view, KHR_materials_
    volume with attenuationColor SLAB_COLOR at attenuationDistance 1: the
    left of ior 1 (no interface at all: SLAB_COLOR^2 exactly), the right of
    ior 1.5; an orthographic camera looks straight through both."""
    buf = Buffer()
    primitives = []
    for material in (0, 1):
        primitive = cube_primitive(buf)
        primitive["material"] = material
        primitives.append(primitive)

    def glass(ior):
        return {"pbrMetallicRoughness": {"metallicFactor": 0.0,
                                         "roughnessFactor": 0.0},
                "extensions": {
                    "KHR_materials_transmission": {"transmissionFactor": 1.0},
                    "KHR_materials_ior": {"ior": ior},
                    "KHR_materials_volume": {
                        "thicknessFactor": 1.0, "attenuationDistance": 1.0,
                        "attenuationColor": list(SLAB_COLOR)}}}
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior",
                           "KHR_materials_volume"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0, "translation": [-0.5, 0.0, 0.0],
                   "scale": [0.9, 0.9, 2.0]},
                  {"mesh": 1, "translation": [0.5, 0.0, 0.0],
                   "scale": [0.9, 0.9, 2.0]},
                  {"camera": 0, "translation": [0.0, 0.0, 5.0]}],
        "meshes": [{"primitives": [primitives[0]]},
                   {"primitives": [primitives[1]]}],
        "materials": [glass(1.0), glass(1.5)],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 0.5, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


def mirrored_quads():
    """Single-sided quads under a mirroring node (scale -1 in x), seen by an
    orthographic camera at z = 3 over [-1, 1]^2 and lit by a directional
    light along -z. Top row: a green quad whose front faces the camera
    (x in [-0.9, -0.1]) and one whose back does (x in [0.1, 0.9], culled).
    Bottom row (y in [-0.9, -0.1]): a white receiver at z = 0 and, over its
    right half (x in [0.1, 0.9]) at z = 0.5, a black quad whose front faces
    the receiver: the camera sees through its back, and so does the light."""
    buf = Buffer()

    def quad(x0, x1, y0, y1, z, facing_camera, material):
        # Stored mirrored in x (the node's scale -1 puts it back), its
        # corners counter-clockwise seen from +z in the mesh: clockwise in
        # the world, the front under the node's negative determinant.
        corners = [(-x1, y0), (-x0, y0), (-x0, y1), (-x1, y1)]
        normal = (0.0, 0.0, 1.0 if facing_camera else -1.0)
        order = [0, 1, 2, 0, 2, 3] if facing_camera else [0, 2, 1, 0, 3, 2]
        return {"attributes": {
            "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                     [(x, y, z) for x, y in corners],
                                     bounds=True),
            "NORMAL": buf.accessor("f", FLOAT, "VEC3", [normal] * 4)},
            "indices": buf.accessor("H", USHORT, "SCALAR", order),
            "material": material}
    primitives = [quad(-0.9, -0.1, 0.1, 0.9, 0.0, True, 0),
                  quad(0.1, 0.9, 0.1, 0.9, 0.0, False, 0),
                  quad(-0.9, 0.9, -0.9, -0.1, 0.0, True, 1),
                  quad(0.1, 0.9, -0.9, -0.1, 0.5, False, 2)]

    def matte(r, g, b):
        return {"pbrMetallicRoughness": {"baseColorFactor": [r, g, b, 1.0],
                                         "metallicFactor": 0.0,
                                         "roughnessFactor": 1.0}}
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0, "scale": [-1.0, 1.0, 1.0]},
                  {"camera": 0, "translation": [0.0, 0.0, 3.0]},
                  {"extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "meshes": [{"primitives": primitives}],
        "materials": [matte(0.1, 0.8, 0.2), matte(0.8, 0.8, 0.8),
                      matte(0.0, 0.0, 0.0)],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": 3.0}]}},
    }
    return finish_gltf(gltf, buf)


def anisotropic_plates(tangents=True):
    """Two white metal plates (roughness 0.3, KHR_materials_anisotropy
    strength 0.8, TANGENT along +x, or none: then u runs along +y) side by
    side at z = 0 over x in [-2, 0] and [0, 2], y in [-1, 1]: the left's
    anisotropy along the tangent, the right's turned by 90 degrees
    (anisotropyRotation). A point light 1 above each plate's centre, an
    orthographic camera looking down -z."""
    buf = Buffer()

    def plate(x0, material):
        corners = [(x0, -1.0), (x0 + 2.0, -1.0), (x0 + 2.0, 1.0), (x0, 1.0)]
        p = {"attributes": {
            "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                     [(x, y, 0.0) for x, y in corners],
                                     bounds=True),
            "NORMAL": buf.accessor("f", FLOAT, "VEC3", [(0.0, 0.0, 1.0)] * 4),
            # u along +x with TANGENT, along +y without (so the generated
            # tangents differ from any frame the device would pick).
            "TEXCOORD_0": buf.accessor("f", FLOAT, "VEC2",
                                       [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0),
                                        (0.0, 0.0)] if tangents else
                                       [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0),
                                        (1.0, 0.0)])},
            "indices": buf.accessor("H", USHORT, "SCALAR", [0, 1, 2, 0, 2, 3]),
            "material": material}
        if tangents:
            p["attributes"]["TANGENT"] = buf.accessor(
                "f", FLOAT, "VEC4", [(1.0, 0.0, 0.0, 1.0)] * 4)
        return p

    def brushed(rotation):
        return {"pbrMetallicRoughness": {"metallicFactor": 1.0,
                                         "roughnessFactor": 0.3},
                "extensions": {"KHR_materials_anisotropy": {
                    "anisotropyStrength": 0.8,
                    "anisotropyRotation": rotation}}}
    lights = [{"extensions": {"KHR_lights_punctual": {"light": 0}},
               "translation": [x, 0.0, 1.0]} for x in (-1.0, 1.0)]
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_materials_anisotropy", "KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0.0, 0.0, 3.0]}] + lights,
        "meshes": [{"primitives": [plate(-2.0, 0), plate(0.0, 1)]}],
        "materials": [brushed(0.0), brushed(math.pi / 2)],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 2.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "intensity": 5.0}]}},
    }
    return finish_gltf(gltf, buf)


def iridescent_glass_box():
    """A smooth single-sided box of clear glass with walls of thickness
    0.005 (KHR_materials_volume) and an iridescent film (ior 1.67, 400 nm,
    as IridescenceLamp's globe), straight in front of an orthographic
    camera that it fills."""
    buf = Buffer()
    primitive = cube_primitive(buf)
    primitive["material"] = 0
    glass = {"pbrMetallicRoughness": {"metallicFactor": 0.0,
                                      "roughnessFactor": 0.0},
             "extensions": {
                 "KHR_materials_transmission": {"transmissionFactor": 1.0},
                 "KHR_materials_volume": {"thicknessFactor": 0.005},
                 "KHR_materials_iridescence": {
                     "iridescenceFactor": 1.0, "iridescenceIor": 1.67,
                     "iridescenceThicknessMaximum": 400.0}}}
    gltf = {
        "asset": {"version": "2.0", "generator": "prism tests/cli/data/make_assets.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_volume",
                           "KHR_materials_iridescence"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0.0, 0.0, 3.0]}],
        "meshes": [{"primitives": [primitive]}],
        "materials": [glass],
        "cameras": [{"type": "orthographic", "orthographic": {
            "xmag": 0.4, "ymag": 0.4, "znear": 0.1, "zfar": 10.0}}],
    }
    return finish_gltf(gltf, buf)


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


KTX2_MAGIC = bytes((0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB,
                    0x0D, 0x0A, 0x1A, 0x0A))


def unsupported_extension_file(extension, case):
    """plane.gltf depending on `extension` in one of three ways: 'required'
    (listed in extensionsRequired, no fallback), 'no-fallback' (only in
    extensionsUsed, but a primitive or texture cannot do without it) or
    'fallback' (only used, uncompressed data or a PNG beside it)."""
    gltf = json.loads(plane_scene())
    gltf["extensionsUsed"] = [extension]
    if case == "required":
        gltf["extensionsRequired"] = [extension]
    primitive = gltf["meshes"][0]["primitives"][0]
    if extension == "KHR_draco_mesh_compression":
        primitive["extensions"] = {extension: {
            "bufferView": 0, "attributes": {"POSITION": 0}}}
        if case != "fallback":
            for accessor in gltf["accessors"]:
                del accessor["bufferView"]
    elif extension == "KHR_texture_basisu":
        primitive["material"] = 0
        gltf["materials"] = [{"pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}}}]
        gltf["images"] = [{"uri": data_uri("image/ktx2", KTX2_MAGIC + bytes(20))}]
        texture = {"extensions": {extension: {"source": 0}}}
        if case == "fallback":
            gltf["images"].append({"uri": "checker.png"})
            texture["source"] = 1
        gltf["textures"] = [texture]
    elif extension == "EXT_meshopt_compression":
        # The views keep pointing at buffer 0; in the dependent cases that
        # is a placeholder for the decompressed data, nothing in it.
        size = gltf["buffers"][0]["byteLength"]
        compressed = {"buffer": 0, "byteLength": size, "byteStride": 12,
                      "mode": "ATTRIBUTES", "count": 4}
        gltf["bufferViews"][0]["extensions"] = {extension: compressed}
        if case != "fallback":
            gltf["buffers"].insert(0, {"byteLength": size, "extensions": {
                extension: {"fallback": True}}})
            for view in gltf["bufferViews"]:
                view["buffer"] = 0
            compressed["buffer"] = 1
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
    for kind in ("lightless", "lit", "emissive"):
        write(kind + "-box.gltf", box_scene(kind))
    write("red-sky.hdr", uniform_hdr(8, 4, (1.0, 0.0, 0.0)))
    write("white-sky.hdr", uniform_hdr(8, 4, (1.0, 1.0, 1.0)))
    write("fresnel-plane.gltf", fresnel_plane())
    write("expected-fresnel-48.pfm", expected_fresnel(48))
    write("glowing.obj", GLOWING_OBJ)
    write("named-normals.obj", NAMED_NORMALS_OBJ)
    write("instanced-grid.gltf", instanced_grid())
    write("sphere.obj", uv_sphere_obj())
    write("variants.gltf", variants_quad())
    write("morphed-quad.gltf", morphed_quad())
    write("skinned-bar.gltf", skinned_bar())
    write("animated-bar.gltf", animated_bar())
    write("normal-mapped-plane.gltf", normal_mapped_plane(None))
    for stem, files in (("unlit", unlit_files()),
                        ("vertex-color-texture", vertex_color_files()),
                        ("spec-gloss", spec_gloss_files())):
        write(stem + ".gltf", files[0])
        write("expected-%s-32.pfm" % stem, files[1])
    write("single-sided.gltf", single_sided_file())
    write("points-lines.gltf", points_lines_file())
    write("attenuation-slabs.gltf", attenuation_slabs())
    write("mirrored-quads.gltf", mirrored_quads())
    write("anisotropic-plates.gltf", anisotropic_plates())
    write("anisotropic-plates-no-tangents.gltf",
          anisotropic_plates(tangents=False))
    write("iridescent-glass.gltf", iridescent_glass_box())
    for extension, stem in (("KHR_draco_mesh_compression", "draco"),
                            ("KHR_texture_basisu", "basisu"),
                            ("EXT_meshopt_compression", "meshopt")):
        for case in ("required", "no-fallback", "fallback"):
            write("%s-%s.gltf" % (stem, case),
                  unsupported_extension_file(extension, case))
    write("normal-mapped-plane-tangents.gltf", normal_mapped_plane("analytic"))
    write("normal-mapped-plane-unmirrored.gltf",
          normal_mapped_plane("unmirrored"))
    write("glowing.mtl", GLOWING_MTL)

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
    missing_texture = json.loads(unsupported_extension_file(
        "KHR_texture_basisu", "fallback"))
    del missing_texture["extensionsUsed"]
    missing_texture["images"] = [{"uri": "no-such-texture.png"}]
    missing_texture["textures"] = [{"source": 0}]
    write("missing-texture.gltf", json.dumps(missing_texture, indent=1))
    write("bad-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    write("garbage.obj", bytes((i * 37 + 11) % 256 for i in range(512)))
    write("nonfinite.obj", NONFINITE_OBJ)
    write("huge-index.obj",
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775808\n")
    write("wrapping-index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n")
    write("tiny_4x4x4_uint8.raw", bytes(range(64)))
    write("truncated_8x8x8_uint16.raw", bytes(1000))
    write("volume.raw", bytes(64))
    # Voxel counts whose product overflows 64 bits.
    write("overflow_999999999x999999999x999999999_uint8.raw", b"abcd")
    write_emissive_label_assets()


def emissive_label_scene():
    """emissive-label.gltf: a grey box (no lights, nothing else emits) with
    a small label on its +z face (0.4 x 0.2, 0.001 in front of it) whose
    material is black and emits pure green (1 on g only). An emissive label
    is no light to see the model by: the box must still be lit by the
    default studio, and red in its pixels can only come from there."""
    buf = Buffer()
    box = cube_primitive(buf)
    box["material"] = 0
    label = {"attributes": {
        "POSITION": buf.accessor("f", FLOAT, "VEC3",
                                 [(-0.2, -0.1, 0.501), (0.2, -0.1, 0.501),
                                  (0.2, 0.1, 0.501), (-0.2, 0.1, 0.501)],
                                 bounds=True),
        "NORMAL": buf.accessor("f", FLOAT, "VEC3", [(0.0, 0.0, 1.0)] * 4)},
        "indices": buf.accessor("H", USHORT, "SCALAR", [0, 1, 2, 0, 2, 3]),
        "material": 1}
    gltf = {
        "asset": {"version": "2.0",
                  "generator": "prism tests/cli/data/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "labelled box", "mesh": 0}],
        "meshes": [{"primitives": [box, label]}],
        "materials": [
            {"name": "grey", "pbrMetallicRoughness": {
                "baseColorFactor": [0.7, 0.7, 0.7, 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.8}},
            {"name": "label", "emissiveFactor": [0.0, 1.0, 0.0],
             "pbrMetallicRoughness": {
                 "baseColorFactor": [0.0, 0.0, 0.0, 1.0],
                 "metallicFactor": 0.0, "roughnessFactor": 1.0}}],
    }
    return finish_gltf(gltf, buf)


def write_emissive_label_assets():
    write("emissive-label.gltf", emissive_label_scene())


if __name__ == "__main__":
    main()
