"""A volume from a numpy array: a 64^3 density (two soft blobs) shared with
the device without a copy, colored by a transfer function.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/volume.py volume.png
"""

import sys

import numpy as np

import prism

output = sys.argv[1] if len(sys.argv) > 1 else "volume.png"
n = 64
z, y, x = np.mgrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j].astype(np.float32)
density = (np.exp(-8 * ((x - 0.3) ** 2 + y ** 2 + z ** 2))
           + np.exp(-12 * ((x + 0.4) ** 2 + (y - 0.2) ** 2 + z ** 2))).astype(np.float32)

device = prism.newDevice()
field = device.newSpatialField("structuredRegular")
field.data = device.newArray(prism.FLOAT32, density)  # shape (z, y, x): x varies fastest
field.set(origin=(-1, -1, -1), spacing=(2 / (n - 1),) * 3).commitParameters()

volume = device.newVolume("transferFunction1D")
volume.value = field
volume.color = np.array([[0.1, 0.0, 0.3], [0.9, 0.3, 0.1], [1.0, 0.9, 0.4]], np.float32)
volume.opacity = np.array([0.0, 0.6, 1.0], np.float32)
volume.set(valueRange=(0.0, float(density.max())), unitDistance=0.3).commitParameters()

world = device.newWorld()
world.volume = [volume]
world.commitParameters()

camera = device.newCamera("perspective")
camera.set(position=(0, 0, 3.2), direction=(0, 0, -1), up=(0, 1, 0), aspect=1.0)
camera.commitParameters()
renderer = device.newRenderer("raycast")
renderer.background = (1, 1, 1, 1)
renderer.commitParameters()

frame = device.newFrame()
frame.set(size=(256, 256), world=world, camera=camera, renderer=renderer)
frame.setParameter("channel.color", prism.UFIXED8_RGBA_SRGB)
frame.commitParameters()
frame.render()
frame.image().save(output)
print(f"wrote {output}")
