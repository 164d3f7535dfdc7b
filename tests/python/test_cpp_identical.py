"""The Cornell box demo built from Python renders bit for bit what
prism-render renders from the C++ scene (scenes/CornellBox.cpp) with the
raycast renderer: same vertices computed in the same float order, same
camera, same frame."""

import ctypes
import os
import subprocess

import numpy as np

import prism
from conftest import build_dir

f32 = np.float32
_libm = ctypes.CDLL("libm.so.6")
_libm.cosf.restype = _libm.sinf.restype = ctypes.c_float
_libm.cosf.argtypes = _libm.sinf.argtypes = [ctypes.c_float]


# The float math of scenes/Math.h, one IEEE single operation at a time.
def add(a, b):
    return [f32(x) + f32(y) for x, y in zip(a, b)]


def sub(a, b):
    return [f32(x) - f32(y) for x, y in zip(a, b)]


def scale(a, s):
    return [f32(x) * f32(s) for x in a]


def cross(a, b):
    a, b = [f32(x) for x in a], [f32(x) for x in b]
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def normalize(a):
    a = [f32(x) for x in a]
    length = np.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
    return scale(a, f32(1) / length) if length > 0 else a


def matmul(a, b):  # column-major 4x4, element (r, c) at 4c + r
    m = [f32(0)] * 16
    for c in range(4):
        for r in range(4):
            total = f32(0)
            for k in range(4):
                total = total + f32(a[4 * k + r]) * f32(b[4 * c + k])
            m[4 * c + r] = total
    return m


def translation(t):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t[0], t[1], t[2], 1]


def scaling(s):
    return [s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1]


def rotation_y(radians):
    c, s = f32(_libm.cosf(radians)), f32(_libm.sinf(radians))
    return [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1]


def point(m, p):
    m, p = [f32(x) for x in m], [f32(x) for x in p]
    return [m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
            m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
            m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]]


def direction(m, d):
    m, d = [f32(x) for x in m], [f32(x) for x in d]
    return [m[0] * d[0] + m[4] * d[1] + m[8] * d[2],
            m[1] * d[0] + m[5] * d[1] + m[9] * d[2],
            m[2] * d[0] + m[6] * d[1] + m[10] * d[2]]


class Mesh:
    def __init__(self):
        self.positions, self.normals, self.uvs, self.tangents, self.triangles = [], [], [], [], []

    def quad(self, corner, edge1, edge2):
        first = len(self.positions)
        normal = normalize(cross(edge1, edge2))
        tangent = normalize(edge1)
        corners = [corner, add(corner, edge1), add(add(corner, edge1), edge2),
                   add(corner, edge2)]
        for i, uv in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
            self.positions.append(corners[i])
            self.normals.append(normal)
            self.uvs.append(uv)
            self.tangents.append(list(tangent) + [1])
        self.triangles += [(first, first + 1, first + 2), (first, first + 2, first + 3)]

    def box(self, m):
        faces = [((-0.5, -0.5, 0.5), (1, 0, 0), (0, 1, 0)),
                 ((0.5, -0.5, -0.5), (-1, 0, 0), (0, 1, 0)),
                 ((0.5, -0.5, 0.5), (0, 0, -1), (0, 1, 0)),
                 ((-0.5, -0.5, -0.5), (0, 0, 1), (0, 1, 0)),
                 ((-0.5, 0.5, 0.5), (1, 0, 0), (0, 0, -1)),
                 ((-0.5, -0.5, -0.5), (1, 0, 0), (0, 0, 1))]
        for corner, e1, e2 in faces:
            self.quad(point(m, corner), direction(m, e1), direction(m, e2))

    def geometry(self, device):
        g = device.newGeometry("triangle")
        g.setParameter("vertex.position", np.array(self.positions, np.float32))
        g.setParameter("vertex.normal", np.array(self.normals, np.float32))
        g.setParameter("vertex.attribute0", np.array(self.uvs, np.float32))
        g.setParameter("vertex.tangent", np.array(self.tangents, np.float32))
        g.setParameter("primitive.index", np.array(self.triangles, np.uint32))
        g.commitParameters()
        return g


def cornell_box(device, width, height):
    white, red, green, boxes, panel = Mesh(), Mesh(), Mesh(), Mesh(), Mesh()
    white.quad((-1, 0, 1), (2, 0, 0), (0, 0, -2))
    white.quad((-1, 2, -1), (2, 0, 0), (0, 0, 2))
    white.quad((-1, 0, -1), (2, 0, 0), (0, 2, 0))
    red.quad((-1, 0, 1), (0, 0, -2), (0, 2, 0))
    green.quad((1, 0, -1), (0, 0, 2), (0, 2, 0))
    boxes.box(matmul(matmul(translation((f32(-0.35), f32(0.6), f32(-0.3))),
                            rotation_y(f32(0.3))), scaling((f32(0.6), f32(1.2), f32(0.6)))))
    boxes.box(matmul(matmul(translation((f32(0.35), f32(0.3), f32(0.35))),
                            rotation_y(f32(-0.3))), scaling((f32(0.6), f32(0.6), f32(0.6)))))
    corner, edge1, edge2 = (f32(-0.25), f32(1.995), f32(-0.25)), (0.5, 0, 0), (0, 0, 0.5)
    panel.quad(corner, edge1, edge2)

    light = device.newLight("quad")
    light.setParameter("position", prism.float3, add(corner, (0, f32(-0.001), 0)))
    light.set(edge1=edge2, edge2=edge1, color=(1.0, 0.85, 0.6), intensity=12.0)
    light.commitParameters()

    def matte(color):
        m = device.newMaterial("matte")
        m.setParameter("color", prism.float3, color)
        return m.commitParameters()

    panel_material = device.newMaterial("physicallyBased")
    panel_material.set(baseColor=(1.0, 1.0, 1.0), metallic=0.0).commitParameters()
    white_material = matte((0.73, 0.73, 0.73))
    parts = [(white, white_material), (red, matte((0.65, 0.05, 0.05))),
             (green, matte((0.12, 0.45, 0.15))), (boxes, white_material),
             (panel, panel_material)]
    surfaces = []
    for id_, (mesh, material) in enumerate(parts):
        s = device.newSurface()
        s.set(geometry=mesh.geometry(device), material=material)
        s.setParameter("id", prism.UINT32, id_)
        surfaces.append(s.commitParameters())
    world = device.newWorld()
    world.set(surface=surfaces, light=[light]).commitParameters()

    eye, at = (f32(0.0031), f32(1.0017), f32(3.9)), (0, 1, 0)
    camera = device.newCamera("perspective")
    camera.set(position=eye, direction=normalize(sub(at, eye)), up=(0, 1, 0),
               aspect=f32(width) / f32(height),
               fovy=f32(40) * f32(np.pi) / f32(180))
    camera.commitParameters()
    renderer = device.newRenderer("raycast").commitParameters()
    frame = device.newFrame()
    frame.set(size=(width, height), world=world, camera=camera, renderer=renderer)
    frame.setParameter("channel.color", prism.FLOAT32_VEC4)
    return frame.commitParameters()


def read_pfm(path):
    with open(path, "rb") as f:
        magic, size, scale_line = f.readline(), f.readline(), f.readline()
        width, height = (int(v) for v in size.split())
        assert magic.strip() == b"PF" and float(scale_line) < 0  # little endian
        return np.frombuffer(f.read(), "<f4").reshape(height, width, 3)


def test_cornell_box_matches_prism_render(device, tmp_path):
    width, height = 64, 48
    output = tmp_path / "cornell.pfm"
    subprocess.run([os.path.join(build_dir(), "bin", "prism-render"),
                    "demo:cornell-box", "--renderer", "raycast", "--size",
                    f"{width}x{height}", "--quiet", "-o", str(output)], check=True)
    from_cpp = read_pfm(output)

    frame = cornell_box(device, width, height)
    frame.render()
    from_python = frame.get("channel.color")[..., :3]

    assert from_python.shape == from_cpp.shape == (height, width, 3)
    assert len(np.unique(from_cpp.reshape(-1, 3), axis=0)) > 20  # a real image
    differing = np.count_nonzero(np.any(from_python != from_cpp, axis=-1))
    assert differing == 0, f"{differing} of {width * height} pixels differ"
