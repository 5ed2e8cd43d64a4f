#pragma once
// STL hull input (ASCII or binary). The mesh is one demihull (both sides or the port side only) in hull axes:
// x from the AP forward, y to port from the demihull centreline, z from the baseline up, metres.
#include <array>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"

namespace hullopt::io {

struct StlMesh {
  std::vector<std::array<std::array<double, 3>, 3>> triangles;  ///< [m] vertices
};

/// Reads an ASCII ("solid ..." with facet/vertex lines) or binary STL. Binary is recognised by its exact size
/// 84 + 50 n bytes. Throws InputError for a missing, empty or truncated file, a non-numeric vertex, a facet
/// without 3 vertices, or a mesh without triangles.
StlMesh ReadStl(const std::string& path);

/// Cuts the mesh by `stations` planes x = const equally spaced over its length and returns the port half
/// contours (y >= 0) from the keel up, as stations of one demihull. Each cut is made a tiny distance
/// (1e-7 of the length) off the nominal x, inwards at the ends, so that planes never pass exactly through
/// vertices; the station keeps its nominal x. Throws InputError (naming `what`, the file) if a cut cannot be
/// turned into a keel-to-deck contour with non-decreasing z, or no station is wetted at draught_m.
hull::Demihull SliceStl(const StlMesh& mesh, int stations, double draught_m, const std::string& what);

/// Writes a binary STL (for tests and exports).
void WriteBinaryStl(const std::string& path, const StlMesh& mesh);

}  // namespace hullopt::io
