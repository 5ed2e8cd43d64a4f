#include "io/formats/stl_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"
#include "io/formats/input_limits.h"

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
        if (!std::isfinite(f) || std::fabs(f) > kMaxCoordinate_m)
          throw InputError(path + ": binary STL triangle " + std::to_string(t + 1) +
                           " has a non-finite or absurd coordinate (|value| <= " +
                           std::to_string(int(kMaxCoordinate_m)) + " m)");
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
        if (std::fabs(v) > kMaxCoordinate_m)
          throw InputError(where + ": vertex coordinate '" + xs[c] + "' is not a hull coordinate (|value| <= " +
                           std::to_string(int(kMaxCoordinate_m)) + " m)");
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
    // Cut segments. Each edge is interpolated in a canonical direction (lexicographically smaller end first)
    // so the two triangles sharing it produce bit-identical points, which then chain by exact comparison.
    using P = std::pair<double, double>;  // (y, z)
    std::vector<std::array<P, 2>> seg;
    for (const auto& t : mesh.triangles) {
      P pts[2];
      int k = 0;
      for (int e = 0; e < 3 && k < 2; ++e) {
        auto a = t[e], b = t[(e + 1) % 3];
        if (!((a[0] - xc) * (b[0] - xc) < 0.0)) continue;
        if (b < a) std::swap(a, b);
        const double f = (xc - a[0]) / (b[0] - a[0]);
        pts[k++] = {a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
      }
      if (k == 2 && pts[0] != pts[1]) seg.push_back({pts[0], pts[1]});
    }
    hull::Station st;
    st.x_m = xn;
    if (seg.empty()) {
      body.stations.push_back(st);
      continue;
    }
    double breadth = 0.0;
    for (const auto& sg : seg) breadth = std::max({breadth, std::fabs(sg[0].first), std::fabs(sg[1].first)});
    const double ytol = 1e-9 * std::max(breadth, 1e-300);
    std::multimap<P, size_t> ends;
    for (size_t k = 0; k < seg.size(); ++k) {
      ends.emplace(seg[k][0], k);
      ends.emplace(seg[k][1], k);
    }
    // The keel: the lowest point on the centreline (|y| within round-off of 0), else the lowest port point.
    P start{0.0, INFINITY};
    bool on_cl = false;
    for (const auto& kv : ends) {
      const P& p = kv.first;
      const bool cl = std::fabs(p.first) <= ytol;
      if (p.first < -ytol) continue;
      if ((cl && !on_cl) || (cl == on_cl && p.second < start.second)) {
        start = p;
        on_cl = cl;
      }
    }
    std::vector<bool> used(seg.size(), false);
    st.y_m.push_back(std::max(0.0, start.first));
    st.z_m.push_back(start.second);
    P at = start;
    // First step: the incident segment leading furthest to port.
    size_t cur = seg.size();
    double best_y = -INFINITY;
    for (auto it = ends.lower_bound(at); it != ends.end() && it->first == at; ++it) {
      const auto& sg = seg[it->second];
      const P& other = sg[0] == at ? sg[1] : sg[0];
      if (other.first >= -ytol && other.first + other.second > best_y) {  // to port and upwards
        best_y = other.first + other.second;
        cur = it->second;
      }
    }
    while (cur < seg.size()) {
      used[cur] = true;
      const P next = seg[cur][0] == at ? seg[cur][1] : seg[cur][0];
      if (next.first < -ytol) break;  // crossed to starboard (over a deck)
      if (next.second < st.z_m.back() - 1e-9 * len) {
        std::ostringstream m;
        m << what << ": STL section at x = " << xn << " m turns downwards at z = " << next.second
          << " m (re-entrant section): stations must rise monotonically from the keel to the deck";
        throw InputError(m.str());
      }
      st.y_m.push_back(std::max(0.0, next.first));
      st.z_m.push_back(std::max(next.second, st.z_m.back()));
      at = next;
      // Next: the unused incident segment that climbs most (then goes furthest to port); where both sides
      // of a zero-breadth keel or stem meet, this keeps the walk going up rather than back down.
      cur = seg.size();
      P best{-INFINITY, -INFINITY};  // (z, y) of the candidate's far end
      for (auto it = ends.lower_bound(at); it != ends.end() && it->first == at; ++it) {
        if (used[it->second]) continue;
        const auto& sg = seg[it->second];
        const P& other = sg[0] == at ? sg[1] : sg[0];
        if (other.first < -ytol) continue;
        if (P{other.second, other.first} > best) {
          best = {other.second, other.first};
          cur = it->second;
        }
      }
      if (cur == seg.size()) {  // only starboard continuations left: the section ends here
        break;
      }
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
  std::ostringstream out(std::ios::binary);
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
  WriteFileAtomically(path, out.str());
}

}  // namespace hullopt::io
