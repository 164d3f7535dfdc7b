"""Frames: render, wait, accumulate and read channels as ndarrays laid out as
ANARI lays them out (row 0 at the bottom); image() turns them upright."""

import io
import logging

import numpy as np

from . import types as T
from .objects import Object

logger = logging.getLogger("prism")


class Frame(Object):
    """An ANARI frame. Set size, world, camera, renderer and the channels'
    types, commitParameters(), then render() and get('channel.color')."""

    def render(self, spp=None):
        """Render and wait. spp > 1 (or a renderer's pixelSamples) renders
        that many samples into the frame's accumulation; the GIL is released
        meanwhile."""
        samples = int(spp) if spp is not None else self._renderer_samples()
        if samples < 1:
            raise ValueError(f"spp must be at least 1, got {samples}")
        if samples > 1:
            self._accumulate()
        # Short waits, so Ctrl-C (KeyboardInterrupt) gets through between
        # them, wherever in the loop it lands; the frame in flight is then
        # discarded and finished before re-raising.
        try:
            for _ in range(samples):
                self._native.renderAsync()
                while not self._native.wait(0.1):
                    pass
        except KeyboardInterrupt:
            self._native.discard()
            self._native.wait(-1.0)
            raise
        return self

    def renderAsync(self):
        """Start rendering and return at once; ready()/wait() tell when done."""
        self._native.renderAsync()
        return self

    def ready(self):
        return self._native.ready()

    def wait(self, timeout=None):
        """Wait until the frame is done, at most `timeout` seconds (None:
        for as long as it takes); returns whether it is done."""
        return self._native.wait(-1.0 if timeout is None else max(0.0, float(timeout)))

    def discard(self):
        self._native.discard()

    @property
    def progress(self):
        """How much of the frame in flight is done, 0 to 1."""
        value = self.getProperty("renderProgress", T.FLOAT32, wait=False)
        return 0.0 if value is None else value

    @property
    def duration(self):
        """Seconds the last frame took to render (waits for it)."""
        return self.getProperty("duration", T.FLOAT32, wait=True)

    def get(self, channel="channel.color"):
        """A channel as an ndarray of shape (height, width[, components]) in
        the channel's own type (uint8 for UFIXED8_RGBA_SRGB, float32 for
        FLOAT32_VEC4 ...), row 0 at the bottom as ANARI lays it out."""
        mapped = self._native.mapChannel(channel)
        if mapped is None:
            raise KeyError(f"the frame has no channel '{channel}' (set its type "
                           f"as the frame parameter '{channel}', commit, render)")
        pixel_type, width, height, raw = mapped
        dtype = T.scalar_dtype(pixel_type)
        components = T.COMPONENTS.get(pixel_type, 1)
        shape = (height, width) if components == 1 else (height, width, components)
        return raw.view(dtype).reshape(shape)

    def image(self, channel="channel.color"):
        """The channel as an upright PIL image (float colors sRGB-encoded)."""
        from PIL import Image
        pixels = np.flipud(self.get(channel))
        if pixels.dtype != np.uint8:
            linear = np.clip(np.nan_to_num(pixels.astype(np.float32)), 0.0, 1.0)
            if pixels.ndim == 3:
                rgb = linear[..., :3]
                encoded = np.where(rgb <= 0.0031308, 12.92 * rgb,
                                   1.055 * np.power(rgb, 1 / 2.4) - 0.055)
                linear = np.concatenate([encoded, linear[..., 3:]], axis=-1)
            pixels = np.round(linear * 255.0).astype(np.uint8)
        modes = {2: "L", 3: "RGB", 4: "RGBA"}
        mode = "L" if pixels.ndim == 2 else modes[pixels.shape[2]]
        return Image.fromarray(np.ascontiguousarray(pixels), mode)

    def _repr_png_(self):
        buffer = io.BytesIO()
        self.image().save(buffer, format="PNG")
        return buffer.getvalue()

    # Accumulation -------------------------------------------------------------

    def _renderer_samples(self):
        renderer = self._values.get("renderer")
        return getattr(renderer, "_samples_per_render", 1) if renderer is not None else 1

    def _accumulate(self):
        if self._values.get("accumulation") is True:
            return
        if "accumulation" in self._values:
            raise ValueError("render(spp > 1) needs the frame's accumulation, "
                             "which is set to false")
        self.setParameter("accumulation", T.BOOL, True)
        self.commitParameters()
