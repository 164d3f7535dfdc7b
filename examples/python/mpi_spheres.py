"""Data-parallel rendering from Python: each MPI process owns a slab of
spheres; the prism_mpi device composites them, rank 0 writes the image.

    mpirun -np 2 env PYTHONPATH=build/python /usr/bin/python3 examples/python/mpi_spheres.py spheres.png
"""

import sys

import numpy as np

import prism

output = sys.argv[1] if len(sys.argv) > 1 else "spheres.png"
device = prism.newDevice("prism_mpi")  # calls MPI_Init itself

frame = device.newFrame()
frame.commitParameters()
rank = frame.getProperty("mpiRank", prism.INT32)
ranks = frame.getProperty("mpiSize", prism.INT32)

# This process's part of the data: a column of spheres at its own x.
rng = np.random.default_rng(rank)
x = -1 + 2 * (rank + 0.5) / ranks
centres = np.column_stack([np.full(8, x), np.linspace(-0.8, 0.8, 8),
                           rng.uniform(-0.2, 0.2, 8)]).astype(np.float32)
spheres = device.newGeometry("sphere")
spheres.setParameter("vertex.position", centres)
spheres.radius = 0.9 / ranks / 2
spheres.commitParameters()
material = device.newMaterial("matte")
material.color = tuple(float(c) for c in rng.uniform(0.2, 1.0, 3))
material.commitParameters()
surface = device.newSurface()
surface.set(geometry=spheres, material=material).commitParameters()
world = device.newWorld()
world.surface = [surface]
world.commitParameters()

camera = device.newCamera("orthographic")
camera.set(position=(0, 0, 3), direction=(0, 0, -1), up=(0, 1, 0), height=2.2,
           aspect=1.0).commitParameters()
renderer = device.newRenderer("raycast")
renderer.commitParameters()
frame.set(size=(128, 128), world=world, camera=camera, renderer=renderer)
frame.setParameter("channel.color", prism.UFIXED8_RGBA_SRGB)
frame.commitParameters()
frame.render()
if rank == 0:
    frame.image().save(output)
    print(f"wrote {output} from {ranks} process(es)")
