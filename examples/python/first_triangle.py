"""The first triangle: one triangle with a color per vertex, rendered by the
prism device and written as a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/first_triangle.py triangle.png
"""

import sys

import numpy as np

import prism

output = sys.argv[1] if len(sys.argv) > 1 else "triangle.png"
device = prism.newDevice()

geometry = device.newGeometry("triangle")
geometry.setParameter("vertex.position", np.array(
    [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32))
geometry.setParameter("vertex.color", np.array(
    [[0.9, 0.1, 0.1, 1], [0.1, 0.9, 0.1, 1], [0.1, 0.1, 0.9, 1]], np.float32))
geometry.commitParameters()

material = device.newMaterial("matte")
material.color = "color"  # the vertex colors
material.commitParameters()

surface = device.newSurface()
surface.set(geometry=geometry, material=material).commitParameters()

light = device.newLight("directional")
light.set(direction=(0, 0, -1), irradiance=2.0).commitParameters()

world = device.newWorld()
world.set(surface=[surface], light=[light]).commitParameters()

camera = device.newCamera("perspective")
camera.set(position=(0, 0, 3), direction=(0, 0, -1), up=(0, 1, 0),
           aspect=4 / 3).commitParameters()

renderer = device.newRenderer("default")
renderer.background = (0.1, 0.1, 0.1, 1)
renderer.commitParameters()

frame = device.newFrame()
frame.set(size=(320, 240), world=world, camera=camera, renderer=renderer)
frame.setParameter("channel.color", prism.UFIXED8_RGBA_SRGB)
frame.commitParameters()
frame.render(spp=16)

pixels = frame.get("channel.color")  # (240, 320, 4) uint8, row 0 at the bottom
frame.image().save(output)
print(f"wrote {output}: {pixels.shape[1]}x{pixels.shape[0]}, "
      f"centre {pixels[120, 160, :3].tolist()}, {frame.duration * 1000:.1f} ms")
