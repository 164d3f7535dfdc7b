"""An isosurface of a numpy field: a gyroid level set, path traced.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/isosurface.py iso.png
"""

import sys

import numpy as np

import prism

output = sys.argv[1] if len(sys.argv) > 1 else "isosurface.png"
n = 48
z, y, x = np.mgrid[0:2 * np.pi:n * 1j, 0:2 * np.pi:n * 1j, 0:2 * np.pi:n * 1j]
gyroid = (np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x))
gyroid = gyroid.astype(np.float32)

device = prism.newDevice()
field = device.newSpatialField("structuredRegular")
field.data = device.newArray(gyroid)
field.set(origin=(-1, -1, -1), spacing=(2 / (n - 1),) * 3).commitParameters()

iso = device.newGeometry("isosurface")
iso.set(field=field, isovalue=0.0).commitParameters()
material = device.newMaterial("physicallyBased")
material.set(baseColor=(0.8, 0.55, 0.2), metallic=0.0, roughness=0.4).commitParameters()
surface = device.newSurface()
surface.set(geometry=iso, material=material).commitParameters()

sun = device.newLight("directional")
sun.set(direction=(-1, -2, -1.5), irradiance=3.0).commitParameters()
world = device.newWorld()
world.set(surface=[surface], light=[sun]).commitParameters()

camera = device.newCamera("perspective")
camera.set(position=(2.2, 1.6, 2.8), direction=(-2.2, -1.6, -2.8), up=(0, 1, 0),
           aspect=1.0).commitParameters()
renderer = device.newRenderer("pathtracer")
renderer.set(background=(0.9, 0.9, 0.95, 1), ambientRadiance=0.4).commitParameters()

frame = device.newFrame()
frame.set(size=(200, 200), world=world, camera=camera, renderer=renderer)
frame.setParameter("channel.color", prism.UFIXED8_RGBA_SRGB)
frame.commitParameters()
frame.render(spp=8)
frame.image().save(output)
print(f"wrote {output}")
