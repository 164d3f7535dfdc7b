// The geometry statements of a Wavefront OBJ file, read by our own parser.
// tinyobjloader (still used for MTL) cannot tell when such a file is wrong:
// it reads `nan` and `inf` as 0, passes 1e39 on as a float infinity, wraps
// face indices past 2^31 (atoi) onto other vertices, and counts a face's
// corners in a byte (255 at most). Here every number is checked:
// - `v x y z [w]` / `v x y z r g b`, `vn x y z`, `vt u [v [w]]`: a value that
//   is missing, unreadable or not a finite float is stored as NaN and
//   counted in `badValues`; the caller drops the faces using it;
// - `f` corners `v`, `v/vt`, `v//vn`, `v/vt/vn` (negative: relative to the
//   vertices so far): an index that is 0, too negative or past the file's
//   count (forward references allowed) is an error naming it and its line;
// - `usemtl`, `mtllib` are recorded; `l` and `p` counted; `o`, `g`, `s` and
//   every other statement skipped.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace prism::scene_io {

// One corner of a face: indices into the parse result's arrays (0-based).
struct ObjCorner
{
  uint32_t position{0};
  int64_t normal{-1}; // -1: none
  int64_t uv{-1};     // -1: none
};

struct ObjFace
{
  size_t firstCorner{0};
  size_t cornerCount{0};
  int material{-1}; // index into materialNames; -1: no usemtl yet
  size_t line{0};   // 1-based, for messages
};

// Values that are not finite numbers, for one warning.
struct ObjBadValues
{
  size_t count{0};       // v, vn and vt statements holding one
  size_t firstLine{0};   // where the first is
  std::string firstText; // and what it says
};

struct ObjParseResult
{
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> colors; // per position, or empty
  std::vector<std::array<float, 3>> normals;
  std::vector<std::array<float, 2>> uvs;
  std::vector<ObjCorner> corners;
  std::vector<ObjFace> faces;
  std::vector<std::string> materialNames;     // in order of first use
  std::vector<std::string> materialLibraries; // mtllib names, as written
  ObjBadValues badValues;
  size_t shortFaces{0}; // faces of fewer than 3 corners (left out)
  // Corners naming a normal (vn) or texture coordinate (vt) of a file that
  // has none at all: used without it (exporters write "f 1//1" regardless).
  size_t cornersWithoutNormals{0};
  size_t cornersWithoutUvs{0};
  size_t linesAndPoints{0}; // l and p statements (not rendered)
  std::string error;        // empty when the file can be used

  bool ok() const
  {
    return error.empty();
  }
};

ObjParseResult parseObj(std::string_view text);

} // namespace prism::scene_io
