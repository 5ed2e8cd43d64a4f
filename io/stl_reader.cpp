#include "io/stl_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "io/input_error.h"

namespace hullopt::io {
namespace {

StlMesh ReadBinary(const std::string& path, const std::string& bytes) {
  uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  StlMesh mesh;
  mesh.triangles.resize(n);
  for (uint32_t t = 0; t < n; ++t) {
    const char* p = bytes.data() + 84 + 50 * size_t(t) + 12;  // skip the normal
    for (int v = 0; v < 3; ++v)
      for (int c = 0; c < 3; ++c) {
        float f;
        std::memcpy(&f, p + 4 * (3 * v + c), 4);
        if (!std::isfinite(f))
          throw InputError(path + ": binary STL triangle " + std::to_string(t + 1) +
                           " has a non-finite coordinate");
        mesh.triangles[t][v][c] = f;
      }
  }
  return mesh;
}

StlMesh ReadAscii(const std::string& path, const std::string& text) {
  StlMesh mesh;
  std::istringstream in(text);
  std::string line;
  int lineno = 0, in_facet = 0;
  std::array<std::array<double, 3>, 3> tri{};
  bool ended = false;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ls(line);
    std::string word;
    if (!(ls >> word)) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    if (word == "facet") {
      in_facet = 1;
    } else if (word == "vertex") {
      if (!in_facet) throw InputError(where + ": 'vertex' outside a facet");
      if (in_facet > 3) throw InputError(where + ": facet has more than 3 vertices");
      std::string xs[3];
      ls >> xs[0] >> xs[1] >> xs[2];
      for (int c = 0; c < 3; ++c) {
        char* end = nullptr;
        const double v = std::strtod(xs[c].c_str(), &end);
        if (xs[c].empty() || *end != '\0' || !std::isfinite(v))
          throw InputError(where + ": vertex coordinate '" + xs[c] + "' is not a finite number");
        tri[in_facet - 1][c] = v;
      }
      ++in_facet;
    } else if (word == "endfacet") {
      if (in_facet != 4)
        throw InputError(where + ": facet has " + std::to_string(std::max(0, in_facet - 1)) +
                         " vertices (need 3)");
      mesh.triangles.push_back(tri);
      in_facet = 0;
    } else if (word == "endsolid") {
      ended = true;
      break;
    }
  }
  if (in_facet)
    throw InputError(path + ":" + std::to_string(lineno) +
                     ": truncated ASCII STL (file ends inside a facet)");
  if (!ended) throw InputError(path + ":" + std::to_string(lineno) + ": truncated ASCII STL (no 'endsolid')");
  return mesh;
}

}  // namespace

StlMesh ReadStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open STL file (does it exist and is it readable?)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw InputError(path + ": STL file is empty");
  StlMesh mesh;
  uint32_t n = 0;
  if (bytes.size() >= 84) std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * uint64_t(n)) {
    mesh = ReadBinary(path, bytes);
  } else if (bytes.compare(0, 5, "solid") == 0) {
    mesh = ReadAscii(path, bytes);
  } else if (bytes.size() < 84) {
    throw InputError(path + ": truncated STL: " + std::to_string(bytes.size()) +
                     " bytes, shorter than a binary STL header (84 bytes) and not ASCII ('solid ...')");
  } else {
    throw InputError(path + ": truncated or corrupt binary STL: header announces " + std::to_string(n) +
                     " triangles (" + std::to_string(84 + 50 * uint64_t(n)) + " bytes) but the file has " +
                     std::to_string(bytes.size()) + " bytes");
  }
  if (mesh.triangles.empty()) throw InputError(path + ": STL file has no triangles");
  return mesh;
}

hull::Demihull SliceStl(const StlMesh& mesh, int stations, double draught_m, const std::string& what) {
  if (stations < 3)
    throw InputError(what + ": need at least 3 stations to slice an STL, got " + std::to_string(stations));
  double x0 = INFINITY, x1 = -INFINITY;
  for (const auto& t : mesh.triangles)
    for (const auto& v : t) {
      x0 = std::min(x0, v[0]);
      x1 = std::max(x1, v[0]);
    }
  const double len = x1 - x0;
  if (!(len > 0.0)) throw InputError(what + ": STL mesh has no length in x");
  const double nudge = 1e-7 * len;
  hull::Demihull body;
  body.role = "demihull";
  int wet = 0;
  for (int i = 0; i < stations; ++i) {
    const double xn = x0 + len * i / (stations - 1);
    const double xc = i == stations - 1 ? xn - nudge : xn + nudge;
    // Cut segments (port side y >= 0 kept after chaining).
    std::vector<std::array<double, 4>> seg;  // y0 z0 y1 z1
    for (const auto& t : mesh.triangles) {
      std::array<double, 2> pts[2];
      int k = 0;
      for (int e = 0; e < 3 && k < 2; ++e) {
        const auto& a = t[e];
        const auto& b = t[(e + 1) % 3];
        if ((a[0] - xc) * (b[0] - xc) < 0.0) {
          const double f = (xc - a[0]) / (b[0] - a[0]);
          pts[k++] = {a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
        }
      }
      if (k == 2) seg.push_back({pts[0][0], pts[0][1], pts[1][0], pts[1][1]});
    }
    hull::Station st;
    st.x_m = xn;
    if (seg.empty()) {
      body.stations.push_back(st);
      continue;
    }
    // Chain segments through shared end points (quantised to tolerate round-off).
    const double q = 1e-9 * len;
    auto key = [&](double y, double z) { return std::make_pair(std::llround(y / q), std::llround(z / q)); };
    std::multimap<std::pair<long long, long long>, size_t> ends;
    for (size_t s = 0; s < seg.size(); ++s) {
      ends.emplace(key(seg[s][0], seg[s][1]), s);
      ends.emplace(key(seg[s][2], seg[s][3]), s);
    }
    // Start at the lowest point on or nearest the centreline on the port side.
    size_t start = 0;
    int start_end = 0;
    double best = INFINITY;
    for (size_t s = 0; s < seg.size(); ++s)
      for (int e = 0; e < 2; ++e) {
        const double y = seg[s][2 * e], z = seg[s][2 * e + 1];
        const double score = z + 1e3 * std::fabs(y);  // centreline first, then lowest
        if (y > -q && score < best) {
          best = score;
          start = s;
          start_end = e;
        }
      }
    std::vector<bool> used(seg.size(), false);
    double y = seg[start][2 * start_end], z = seg[start][2 * start_end + 1];
    st.y_m.push_back(std::max(0.0, y));
    st.z_m.push_back(z);
    size_t cur = start;
    int from = start_end;
    // Walk: leave the start point along the segment that goes to y >= 0.
    const int other0 = 1 - start_end;
    if (seg[start][2 * other0] <
        -q) {  // this segment goes to starboard: find the other one at the start point
      auto range = ends.equal_range(key(y, z));
      for (auto it = range.first; it != range.second; ++it)
        if (it->second != start) {
          cur = it->second;
          from = key(seg[cur][0], seg[cur][1]) == key(y, z) ? 0 : 1;
          break;
        }
    }
    while (true) {
      used[cur] = true;
      const int to = 1 - from;
      const double ny = seg[cur][2 * to], nz = seg[cur][2 * to + 1];
      if (ny < -q) break;  // crossed to starboard (over a deck)
      if (nz < st.z_m.back() - 1e-9 * len) {
        std::ostringstream m;
        m << what << ": STL section at x = " << xn << " m turns downwards at z = " << nz
          << " m (re-entrant section): stations must rise monotonically from the keel to the deck";
        throw InputError(m.str());
      }
      st.y_m.push_back(std::max(0.0, ny));
      st.z_m.push_back(std::max(nz, st.z_m.back()));
      auto range = ends.equal_range(key(ny, nz));
      size_t next = seg.size();
      for (auto it = range.first; it != range.second; ++it)
        if (!used[it->second]) next = it->second;
      if (next == seg.size()) break;
      from = key(seg[next][0], seg[next][1]) == key(ny, nz) ? 0 : 1;
      cur = next;
    }
    if (st.z_m.front() <= draught_m) {
      ++wet;
      if (st.z_m.back() < draught_m) {
        std::ostringstream m;
        m << what << ": STL section at x = " << xn
          << " m has no waterline crossing at draught_m = " << draught_m
          << " (its top is at z = " << st.z_m.back() << " m)";
        throw InputError(m.str());
      }
    }
    body.stations.push_back(st);
  }
  if (wet == 0) {
    std::ostringstream m;
    m << what << ": no STL section reaches below the waterline at draught_m = " << draught_m;
    throw InputError(m.str());
  }
  return body;
}

void WriteBinaryStl(const std::string& path, const StlMesh& mesh) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path + ": cannot write STL file");
  char header[80] = "hullopt binary STL";
  out.write(header, 80);
  const uint32_t n = uint32_t(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : mesh.triangles) {
    const float normal[3] = {0, 0, 0};
    out.write(reinterpret_cast<const char*>(normal), 12);
    for (const auto& v : t)
      for (double c : v) {
        const float f = float(c);
        out.write(reinterpret_cast<const char*>(&f), 4);
      }
    const uint16_t attr = 0;
    out.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

}  // namespace hullopt::io
