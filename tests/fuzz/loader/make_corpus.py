#!/usr/bin/env python3
"""Writes fuzz_loader's seed corpus into corpus/ and its dictionary
fuzz_loader.dict (the outputs are committed; rerun after changing this). Each file is one format byte (0 glTF JSON,
1 GLB, 2 OBJ, 3 OBJ + MTL after a NUL byte, 4 NanoVDB) and the file itself: valid
scenes that reach most of the loaders' mapping, and edge cases each broken
in one way. The glTF scenes are built with the CLI tests' asset helpers
(tests/cli/data/make_assets.py). The NanoVDB seeds need a file NanoVDB
wrote: give the CLI tests' small-zip.nvdb (build/tests/cli/nvdb/, from
write_nanovdb_files) as the first argument."""
import base64
import json
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "cli", "data"))
import make_assets as assets  # noqa: E402

GLTF, GLB, OBJ, OBJ_MTL, NANOVDB = 0, 1, 2, 3, 4
FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125


def write(name, kind, payload):
    if isinstance(payload, str):
        payload = payload.encode()
    assert len(payload) < 8192, name
    with open(os.path.join(HERE, "corpus", name), "wb") as f:
        f.write(bytes([kind]) + payload)


def glb(gltf, data):
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    data = bytes(data) + b"\x00" * (-len(data) % 4)
    body = (struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(data)) + b"BIN\x00" + data)
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def data_uri(data, mime="application/octet-stream"):
    return "data:%s;base64,%s" % (mime, base64.b64encode(bytes(data)).decode())


def small_png():
    rows = [[(x * 60, y * 60, 200, 255) for x in range(4)] for y in range(4)]
    return assets.png_rgba(4, 4, rows)


def textured_gltf():
    """The CLI tests' textured scene with its PNG as a data URI."""
    gltf = json.loads(assets.textured_scene(binary=False))
    gltf["images"] = [{"uri": data_uri(small_png(), "image/png")}]
    return json.dumps(gltf, separators=(",", ":"))


def everything_gltf():
    """One of most things the loader maps: every KHR_materials extension with
    textures, strips and fans, sparse and quantized accessors, no indices,
    both camera types, three light types, a skin and morph target (noted),
    a matrix node, and no `scenes` (roots found from the node graph)."""
    buf = assets.Buffer()
    quad, quad_indices = assets.quad_accessors(buf)
    positions = buf.accessor("f", FLOAT, "VEC3",
                             [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)],
                             bounds=True)
    uv8 = buf.accessor("B", UBYTE, "VEC2",
                       [(0, 0), (255, 0), (0, 255), (255, 255)],
                       normalized=True)
    colors = buf.accessor("H", USHORT, "VEC3", [(65535, 0, 0)] * 4,
                          normalized=True)
    sparse_base = buf.accessor("f", FLOAT, "VEC3", [(0, 0, 0)] * 4)
    buf.accessors[sparse_base]["sparse"] = {
        "count": 1,
        "indices": {"bufferView": buf.view(struct.pack("<I", 2)),
                    "componentType": UINT},
        "values": {"bufferView": buf.view(struct.pack("<3f", 0, 0, 1))}}
    image_view = buf.view(small_png())
    tex = {"index": 0, "texCoord": 0,
           "extensions": {"KHR_texture_transform": {
               "offset": [0.5, 0], "rotation": 0.3, "scale": [2, 2],
               "texCoord": 1}}}
    material_extensions = {
        "KHR_materials_clearcoat": {"clearcoatFactor": 1,
                                    "clearcoatTexture": tex,
                                    "clearcoatRoughnessTexture": {"index": 0},
                                    "clearcoatNormalTexture": {"index": 0,
                                                               "scale": 2}},
        "KHR_materials_emissive_strength": {"emissiveStrength": 3},
        "KHR_materials_ior": {"ior": 1.3},
        "KHR_materials_iridescence": {"iridescenceFactor": 1,
                                      "iridescenceThicknessTexture": {"index": 0}},
        "KHR_materials_sheen": {"sheenColorFactor": [1, 0, 0],
                                "sheenRoughnessTexture": {"index": 0}},
        "KHR_materials_specular": {"specularTexture": {"index": 0},
                                   "specularColorTexture": {"index": 0}},
        "KHR_materials_transmission": {"transmissionFactor": 0.5,
                                       "transmissionTexture": {"index": 0}},
        "KHR_materials_volume": {"thicknessFactor": 1,
                                 "attenuationDistance": 2,
                                 "attenuationColor": [1, 0.5, 0.5]},
    }
    gltf = {
        "asset": {"version": "2.0"},
        "extensionsUsed": sorted(material_extensions) + [
            "KHR_texture_transform", "KHR_lights_punctual",
            "KHR_mesh_quantization", "EXT_unknown"],
        "nodes": [
            {"mesh": 0, "children": [1, 2, 3], "skin": 0,
             "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1]},
            {"mesh": 1, "scale": [2, 2, 2], "rotation": [0, 0.383, 0, 0.924]},
            {"camera": 0, "translation": [0, 0, 5]},
            {"camera": 1, "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"mesh": 2, "scale": [0, 1, 1]},
            {"extensions": {"KHR_lights_punctual": {"light": 2}},
             "translation": [1, 2, 3]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "meshes": [
            {"primitives": [{"attributes": quad, "indices": quad_indices,
                             "material": 0},
                            {"attributes": {"POSITION": positions,
                                            "TEXCOORD_0": uv8,
                                            "TEXCOORD_1": uv8,
                                            "COLOR_0": colors},
                             "mode": 5, "material": 1,
                             "targets": [{"POSITION": sparse_base}]}]},
            {"primitives": [{"attributes": {"POSITION": positions}, "mode": 6},
                            {"attributes": {"POSITION": sparse_base},
                             "mode": 1}]},
            {"primitives": [{"attributes": {"POSITION": positions},
                             "material": 2}]},
        ],
        "materials": [
            {"pbrMetallicRoughness": {"baseColorTexture": tex,
                                      "metallicRoughnessTexture": {"index": 0},
                                      "baseColorFactor": [1, 0.5, 0.5, 0.8]},
             "normalTexture": {"index": 0, "scale": 0.5},
             "occlusionTexture": {"index": 0, "strength": 0.5},
             "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 0],
             "alphaMode": "MASK", "alphaCutoff": 0.3,
             "extensions": material_extensions},
            {"alphaMode": "BLEND", "doubleSided": True},
            {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        ],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "wrapS": 33071, "wrapT": 33648}],
        "images": [{"bufferView": image_view, "mimeType": "image/png"}],
        "cameras": [
            {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
            {"type": "orthographic", "orthographic": {
                "xmag": 2, "ymag": 2, "znear": 0.1, "zfar": 10}}],
        "skins": [{"joints": [1], "inverseBindMatrices": sparse_base}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "intensity": 3},
            {"type": "spot", "color": [1, 0, 0], "intensity": 10,
             "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
            {"type": "point", "range": 5}]}},
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    return gltf, buf.data


def star_obj(corners, decimals=3):
    lines = []
    for i in range(corners):
        a = 2 * math.pi * i / corners
        r = 1.0 if i % 2 == 0 else 0.6
        lines.append("v %.*f %.*f 0" % (decimals, r * math.cos(a),
                                       decimals, r * math.sin(a)))
    lines.append("f " + " ".join(str(i + 1) for i in range(corners)))
    return "\n".join(lines) + "\n"


FEATURES_OBJ = """# every statement the parser reads
mtllib a.mtl b.mtl
o thing
v 0 0 0 1 0 0
v 1 0 0 0 1 0
v 1 1 0 0 0 1
v 0 1 0
v 0.5 0.5 1 0.5
vt 0 0
vt 1
vt 1 1 0
vn 0 0 1
vn 0 0 -1
g group
s 1
usemtl red
f 1/1/1 2/2/1 3/3/1 4/1/1
f -5//2 -4//2 -1//2
usemtl blue
f 1/1 2/2 5/3
usemtl nowhere
f 2 3 5
l 1 2 3
p 4
f 1 2
curv 0 1 1 2
\r
f 3 4 5\r
"""

MATERIALS_MTL = """newmtl red
Kd 1 0 0
Ks 0.5 0.5 0.5
Ns 20
Pr 0.3
Pm 1
map_Kd -s 2 2 1 red.png
map_bump bump.png
newmtl blue
Kd 0 0 1
d 0.4
Ke 0 0 2
Ni 1.5
norm normal.png
map_d alpha.png
"""


GLTF_KEYS = """asset version scene scenes nodes children mesh meshes camera
cameras skin skins matrix rotation scale translation primitives attributes
indices material materials mode targets POSITION NORMAL TANGENT TEXCOORD_0
TEXCOORD_1 TEXCOORD_2 TEXCOORD_3 COLOR_0 JOINTS_0 WEIGHTS_0 accessors
bufferView bufferViews buffer buffers byteOffset byteLength byteStride
componentType count type normalized sparse values min max uri mimeType images
image textures texture source sampler samplers magFilter minFilter wrapS wrapT
index texCoord strength pbrMetallicRoughness baseColorFactor baseColorTexture
metallicFactor roughnessFactor metallicRoughnessTexture normalTexture
occlusionTexture emissiveTexture emissiveFactor alphaMode alphaCutoff
doubleSided extensions extensionsUsed extensionsRequired extras perspective
orthographic yfov ymag xmag znear zfar aspectRatio KHR_lights_punctual lights
light color intensity spot innerConeAngle outerConeAngle range
KHR_texture_transform offset KHR_mesh_quantization KHR_materials_clearcoat
clearcoatFactor clearcoatTexture clearcoatRoughnessFactor
clearcoatRoughnessTexture clearcoatNormalTexture
KHR_materials_emissive_strength emissiveStrength KHR_materials_ior ior
KHR_materials_iridescence iridescenceFactor iridescenceTexture iridescenceIor
iridescenceThicknessMinimum iridescenceThicknessMaximum
iridescenceThicknessTexture KHR_materials_sheen sheenColorFactor
sheenColorTexture sheenRoughnessFactor sheenRoughnessTexture
KHR_materials_specular specularFactor specularTexture specularColorFactor
specularColorTexture KHR_materials_transmission transmissionFactor
transmissionTexture KHR_materials_volume thicknessFactor thicknessTexture
attenuationDistance attenuationColor joints inverseBindMatrices skeleton
animations channels input output interpolation path node""".split()
GLTF_VALUES = ["SCALAR", "VEC2", "VEC3", "VEC4", "MAT4", "OPAQUE", "MASK",
               "BLEND", "directional", "point", "spot", "perspective",
               "orthographic", "data:application/octet-stream;base64,",
               "data:image/png;base64,"]
OBJ_KEYWORDS = ["v ", "vn ", "vt ", "f ", "l ", "p ", "o ", "g ", "s ",
                "usemtl ", "mtllib ", "# "]
MTL_KEYWORDS = ["newmtl ", "Kd ", "Ks ", "Ka ", "Ke ", "Ns ", "Ni ", "d ",
                "Tr ", "Pr ", "Pm ", "illum ", "map_Kd ", "map_Ks ",
                "map_bump ", "bump ", "norm ", "map_d ", "-s ", "-o ",
                "-clamp on "]
EDGE_NUMBERS = ["0", "-1", "1.5", "4294967296", "4294967297", "2147483648",
                "-2147483649", "9223372036854775808", "18446744073709551616",
                "1e39", "-1e39", "1e308", "1e-400", "nan", "inf", "-inf", "/",
                "//", "\\x0d\\x0a", "\\x00"]


def dictionary():
    def name(text):
        return "".join(c if c.isalnum() else "_" for c in text.strip()) or "_"
    lines = ["# fuzz_loader's dictionary (written by make_corpus.py): glTF keys",
             "# and values, GLB chunk tags, OBJ and MTL keywords, numbers at the",
             "# edges of int and float, NanoVDB's magic and codecs."]
    lines += ['gltf_key_%s="\\"%s\\":"' % (k, k) for k in GLTF_KEYS]
    lines += ['gltf_value_%s="\\"%s\\""' % (name(v), v) for v in GLTF_VALUES]
    lines += ['glb_magic="glTF"', 'glb_json="JSON"', 'glb_bin="BIN\\x00"',
              'glb_version="\\x02\\x00\\x00\\x00"']
    lines += ['obj_%s="%s"' % (name(k), k) for k in OBJ_KEYWORDS]
    lines += ['mtl_%s="%s"' % (name(k), k) for k in MTL_KEYWORDS]
    lines += ['number_%d="%s"' % (i, n) for i, n in enumerate(EDGE_NUMBERS)]
    # NanoVDB: the file magic, codecs NONE/ZIP/BLOSC, 2^32 - 16 (a size).
    lines += ['nvdb_magic="NanoVDB0"', 'nvdb_codec_none="\\x00\\x00"',
              'nvdb_codec_zip="\\x01\\x00"', 'nvdb_codec_blosc="\\x02\\x00"',
              'nvdb_huge="\\xf0\\xff\\xff\\xff"']
    with open(os.path.join(HERE, "fuzz_loader.dict"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    dictionary()
    os.makedirs(os.path.join(HERE, "corpus"), exist_ok=True)
    # glTF (JSON)
    write("gltf-plane", GLTF, assets.plane_scene())
    write("gltf-textured", GLTF, textured_gltf())
    gltf, data = everything_gltf()
    gltf_text = dict(gltf)
    gltf_text["buffers"] = [{"byteLength": len(data), "uri": data_uri(data)}]
    write("gltf-everything", GLTF, json.dumps(gltf_text, separators=(",", ":")))
    plane = json.loads(assets.plane_scene())
    edits = {
        "gltf-cycle": lambda g: g.update(nodes=[{"mesh": 0, "children": [1]},
                                                {"children": [0]}]),
        "gltf-mesh-2pow32": lambda g: g["nodes"][0].update(mesh=2 ** 32),
        "gltf-scene-past-end": lambda g: g.update(scene=5),
        "gltf-accessor-past-buffer":
            lambda g: g["accessors"][0].update(count=100000),
        "gltf-index-past-vertices": lambda g: g["bufferViews"][3].update(
            byteLength=8),
        "gltf-external-buffer":
            lambda g: g["buffers"][0].update(uri="/dev/stdin"),
        "gltf-requires-extension":
            lambda g: g.update(extensionsRequired=["KHR_draco_mesh_compression"]),
        "gltf-no-scene": lambda g: g.pop("scenes"),
        "gltf-huge-zero-accessor": lambda g: (
            g["accessors"][0].pop("bufferView"),
            g["accessors"][0].update(count=2 ** 28 - 1)),
        "gltf-nan-matrix": lambda g: g["nodes"][0].update(
            matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1e39, 1]),
    }
    for name, edit in edits.items():
        g = json.loads(json.dumps(plane))
        edit(g)
        write(name, GLTF, json.dumps(g, separators=(",", ":")))
    write("gltf-not-json", GLTF, '{"asset": {"version": "2.0"}, "meshes": [')
    # GLB
    textured = assets.textured_scene(binary=True)
    gltf_bin = dict(gltf)
    gltf_bin["buffers"] = [{"byteLength": len(data)}]
    write("glb-everything", GLB, glb(gltf_bin, data))
    write("glb-truncated", GLB, textured[: len(textured) // 2])
    write("glb-bad-chunk-length", GLB,
          textured[:12] + struct.pack("<I", 0xFFFFFFF0) + textured[16:200])
    # OBJ
    write("obj-cube", OBJ, assets.CUBE_OBJ)
    write("obj-features", OBJ, FEATURES_OBJ)
    write("obj-star-40", OBJ, star_obj(40))
    write("obj-star-300", OBJ, star_obj(300, decimals=2))
    write("obj-nonfinite", OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\n"
          "v 0 inf 0\nv 0 0 1e39\nvn 0 0 -inf\nvt nan 0\n"
          "f 1 2 3\nf 1 2 4\nf 1 2 5\nf 1 2 6\nf 1//1 2//1 3//1\nf 1/1 2/1 3/1\n")
    write("obj-huge-index", OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
          "f 1 2 9223372036854775808\n")
    write("obj-bad-corner", OBJ, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n")
    # OBJ + MTL
    write("objmtl-cube", OBJ_MTL, assets.CUBE_OBJ + "\0" + assets.CUBE_MTL)
    write("objmtl-features", OBJ_MTL, FEATURES_OBJ + "\0" + MATERIALS_MTL)
    # NanoVDB: a 4^3 ball, ZIP-compressed (small), whole and cut short.
    if len(sys.argv) > 1:
        with open(sys.argv[1], "rb") as f:
            nvdb = f.read()
        write("nvdb-small-zip", NANOVDB, nvdb)
        write("nvdb-small-zip-truncated", NANOVDB, nvdb[: len(nvdb) // 2])


if __name__ == "__main__":
    main()
