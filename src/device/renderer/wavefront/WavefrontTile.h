// What a wavefront renderer's TileWork holds: the frame, the tile and its
// buffers, a workspace from the renderer's pool, and the tile's pixels
// numbered row by row (the tags their rays carry).
#pragma once

#include "../Renderer.h"
#include "WorkspacePool.h"

namespace prism {

template <typename Workspace>
class WavefrontTile : public TileWork
{
 protected:
  WavefrontTile(const RenderContext &context,
      const Tile &tile,
      FrameBuffers &buffers,
      WorkspacePool<Workspace> &pool)
      : m_context(context),
        m_tile(tile),
        m_buffers(buffers),
        m_width(tile.x1 - tile.x0),
        m_count(size_t(m_width) * (tile.y1 - tile.y0)),
        m_workspace(pool.take())
  {}

  // The number of pixel (x, y) of the tile.
  size_t indexOf(uint32_t x, uint32_t y) const
  {
    return size_t(y - m_tile.y0) * m_width + (x - m_tile.x0);
  }
  uint2 pixelOf(size_t i) const
  {
    return uint2{
        m_tile.x0 + uint32_t(i % m_width), m_tile.y0 + uint32_t(i / m_width)};
  }

  const RenderContext &m_context;
  const Tile m_tile;
  FrameBuffers &m_buffers;
  const uint32_t m_width;
  const size_t m_count; // pixels
  const typename WorkspacePool<Workspace>::Lease m_workspace;
};

} // namespace prism
