#include "shapes/loop_subdivision.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <fmt/format.h>

#include "core/constants.h"

namespace eyetrace {

namespace {

using DVec3 = glm::dvec3;
using Face = std::array<int, 3>;
constexpr int kNone = -1;

int next(int k) { return (k + 1) % 3; }
int prev(int k) { return (k + 2) % 3; }

uint64_t edge_key(int a, int b) { return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b)); }

struct Level {
  std::vector<DVec3> p;
  std::vector<Face> faces;
};

// The neighbours pbrt-v4's subdivision walks: across[f][k] is the triangle on the other side
// of edge (v[k], v[k+1]) of triangle f; each vertex has one triangle it is in.
struct Topology {
  std::vector<Face> across;
  std::vector<int> start_face;
  std::vector<uint8_t> boundary;

  const Level* m = nullptr;
  int slot(int f, int v) const {
    const Face& face = m->faces[size_t(f)];
    return face[0] == v ? 0 : face[1] == v ? 1 : 2;
  }
  int next_face(int f, int v) const { return across[size_t(f)][size_t(slot(f, v))]; }
  int prev_face(int f, int v) const { return across[size_t(f)][size_t(prev(slot(f, v)))]; }
  int next_vert(int f, int v) const { return m->faces[size_t(f)][size_t(next(slot(f, v)))]; }
  int prev_vert(int f, int v) const { return m->faces[size_t(f)][size_t(prev(slot(f, v)))]; }

  // The vertices around v in pbrt-v4's order: interior vertices from the start triangle's next
  // vertex on, going away from its previous vertex; boundary vertices from one boundary
  // neighbour across the fan to the other (so the ring's ends are the boundary neighbours).
  std::vector<int> ring(int v) const {
    std::vector<int> r;
    int f = start_face[size_t(v)];
    if (!boundary[size_t(v)]) {
      do {
        r.push_back(next_vert(f, v));
        f = next_face(f, v);
      } while (f != start_face[size_t(v)]);
      return r;
    }
    while (next_face(f, v) != kNone) f = next_face(f, v);
    r.push_back(next_vert(f, v));
    do {
      r.push_back(prev_vert(f, v));
      f = prev_face(f, v);
    } while (f != kNone);
    return r;
  }
};

// Pairs the triangles across each edge, refusing what pbrt-v4's pointer walk would
// misread (an edge of three triangles, neighbours of opposite orientation, a vertex where
// separate fans meet), and marks boundary vertices.
Topology build_topology(const Level& m) {
  Topology t;
  t.m = &m;
  t.across.assign(m.faces.size(), Face{kNone, kNone, kNone});
  t.start_face.assign(m.p.size(), kNone);
  t.boundary.assign(m.p.size(), 0);
  std::vector<int> incident(m.p.size(), 0);
  std::unordered_map<uint64_t, std::array<int, 3>> edges;  // key -> (face, k, paired)
  edges.reserve(m.faces.size() * 2);
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const Face& face = m.faces[f];
    for (int k = 0; k < 3; ++k) {
      const int a = face[size_t(k)], b = face[size_t(next(k))];
      if (a == b) throw LoopSubdivisionError(fmt::format("triangle {} uses vertex {} twice", f, a));
      t.start_face[size_t(a)] = int(f);
      ++incident[size_t(a)];
      auto [it, inserted] = edges.try_emplace(edge_key(a, b), std::array<int, 3>{int(f), k, 0});
      if (inserted) continue;
      auto& [f0, k0, paired] = it->second;
      if (paired) throw LoopSubdivisionError(fmt::format("edge ({}, {}) is shared by more than two triangles", a, b));
      if (m.faces[size_t(f0)][size_t(k0)] == a)
        throw LoopSubdivisionError(fmt::format(
            "triangles {} and {} run the same way along their shared edge ({}, {}): their orientations disagree", f0, f,
            a, b));
      t.across[size_t(f0)][size_t(k0)] = int(f);
      t.across[f][size_t(k)] = f0;
      paired = 1;
    }
  }
  for (size_t v = 0; v < m.p.size(); ++v) {
    const int start = t.start_face[v];
    int count = 1, f = start;
    while ((f = t.next_face(f, int(v))) != kNone && f != start && count <= incident[v]) ++count;
    if (f == kNone) {
      t.boundary[v] = 1;
      for (f = start; (f = t.prev_face(f, int(v))) != kNone && count <= incident[v];) ++count;
    }
    if (count != incident[v])
      throw LoopSubdivisionError(
          fmt::format("vertex {} joins separate fans of triangles (the mesh is not a manifold there)", v));
  }
  return t;
}

// Warren's weight, as pbrt-v4 (3/16 at valence 3; 1/16 at the regular valence 6).
double beta(size_t valence) { return valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * double(valence)); }

DVec3 one_ring_rule(const Level& m, int v, const std::vector<int>& ring, double w) {
  DVec3 sum(0.0);
  for (int r : ring) sum += m.p[size_t(r)];
  return (1.0 - double(ring.size()) * w) * m.p[size_t(v)] + w * sum;
}

DVec3 boundary_rule(const Level& m, int v, const std::vector<int>& ring, double w) {
  return (1.0 - 2.0 * w) * m.p[size_t(v)] + w * (m.p[size_t(ring.front())] + m.p[size_t(ring.back())]);
}

Level subdivide(const Level& m) {
  const Topology t = build_topology(m);
  Level out;
  out.p.resize(m.p.size());
  for (size_t v = 0; v < m.p.size(); ++v) {
    const std::vector<int> ring = t.ring(int(v));
    out.p[v] =
        t.boundary[v] ? boundary_rule(m, int(v), ring, 1.0 / 8.0) : one_ring_rule(m, int(v), ring, beta(ring.size()));
  }
  std::unordered_map<uint64_t, int> odd;
  odd.reserve(m.faces.size() * 2);
  auto odd_vertex = [&](size_t f, int k) {
    const int a = m.faces[f][size_t(k)], b = m.faces[f][size_t(next(k))];
    auto [it, inserted] = odd.try_emplace(edge_key(a, b), int(out.p.size()));
    if (!inserted) return it->second;
    const int other = t.across[f][size_t(k)];
    if (other == kNone) {
      out.p.push_back(0.5 * (m.p[size_t(a)] + m.p[size_t(b)]));
    } else {
      // In the neighbour the edge runs b -> a (orientations agree), so its third vertex follows a.
      const int c = m.faces[f][size_t(prev(k))], opposite = t.next_vert(other, a);
      out.p.push_back(3.0 / 8.0 * (m.p[size_t(a)] + m.p[size_t(b)]) +
                      1.0 / 8.0 * (m.p[size_t(c)] + m.p[size_t(opposite)]));
    }
    return it->second;
  };
  out.faces.reserve(m.faces.size() * 4);
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const Face& v = m.faces[f];
    const int e0 = odd_vertex(f, 0), e1 = odd_vertex(f, 1), e2 = odd_vertex(f, 2);
    // pbrt-v4's children: one at each corner, the middle one last; all keep the winding.
    out.faces.push_back({v[0], e0, e2});
    out.faces.push_back({e0, v[1], e1});
    out.faces.push_back({e2, e1, v[2]});
    out.faces.push_back({e0, e1, e2});
  }
  return out;
}

// A control mesh that is a manifold can become one that is not (two triangles on the same
// three vertices): the message then says at which step.
Level subdivide_levels(Level m, int levels) {
  for (int i = 0; i < levels; ++i) try {
      m = subdivide(m);
    } catch (const LoopSubdivisionError& e) {
      if (i == 0) throw;
      throw LoopSubdivisionError(fmt::format("after {} subdivision steps: {}", i, e.what()));
    }
  return m;
}

// The control mesh, checked, with the vertices no triangle uses dropped.
Level control_mesh(const std::vector<Vec3>& positions, const std::vector<int>& indices, int levels) {
  if (levels < 0) throw LoopSubdivisionError(fmt::format("{} levels: must be at least 0", levels));
  if (indices.empty() || indices.size() % 3 != 0)
    throw LoopSubdivisionError(fmt::format("{} vertex indices: need a positive multiple of 3", indices.size()));
  const double triangles = double(indices.size() / 3) * std::pow(4.0, levels);
  if (triangles > double(1 << 26))
    throw LoopSubdivisionError(fmt::format("{} levels would make {:.3g} triangles (at most 2^26)", levels, triangles));
  std::vector<int> remap(positions.size(), kNone);
  Level m;
  for (size_t i = 0; i < indices.size(); ++i) {
    const int v = indices[i];
    if (v < 0 || size_t(v) >= positions.size())
      throw LoopSubdivisionError(
          fmt::format("index {} (entry {}) is out of range: there are {} vertices", v, i, positions.size()));
    if (remap[size_t(v)] == kNone) {
      remap[size_t(v)] = int(m.p.size());
      m.p.push_back(DVec3(positions[size_t(v)]));
    }
  }
  for (size_t i = 0; i < indices.size(); i += 3)
    m.faces.push_back({remap[size_t(indices[i])], remap[size_t(indices[i + 1])], remap[size_t(indices[i + 2])]});
  return m;
}

MeshData to_mesh(const Level& m, const std::vector<DVec3>& normals) {
  MeshData out;
  for (const DVec3& p : m.p) out.positions.push_back(Vec3(p));
  for (const Face& f : m.faces) out.indices.insert(out.indices.end(), f.begin(), f.end());
  for (const DVec3& n : normals) out.normals.push_back(Vec3(n));
  return out;
}

// The tangents of the limit surface at v from its (limit) one-ring, pbrt-v4's masks.
DVec3 limit_normal(const Level& m, const Topology& t, int v) {
  const std::vector<int> ring = t.ring(v);
  const size_t n = ring.size();
  auto p = [&](size_t j) { return m.p[size_t(ring[j])]; };
  DVec3 s(0.0), tan(0.0);
  if (!t.boundary[size_t(v)]) {
    for (size_t j = 0; j < n; ++j) {
      const double a = 2.0 * kPiDouble * double(j) / double(n);
      s += std::cos(a) * p(j);
      tan += std::sin(a) * p(j);
    }
    return glm::cross(s, tan);
  }
  const DVec3 c = m.p[size_t(v)];
  s = p(n - 1) - p(0);
  if (n == 2) {
    tan = p(0) + p(1) - 2.0 * c;
  } else if (n == 3) {
    tan = p(1) - c;
  } else if (n == 4) {  // the regular boundary vertex
    tan = -p(0) + 2.0 * p(1) + 2.0 * p(2) - p(3) - 2.0 * c;
  } else {
    const double theta = kPiDouble / double(n - 1);
    tan = std::sin(theta) * (p(0) + p(n - 1));
    for (size_t k = 1; k + 1 < n; ++k) tan += (2.0 * std::cos(theta) - 2.0) * std::sin(double(k) * theta) * p(k);
    tan = -tan;
  }
  return glm::cross(s, tan);
}

}  // namespace

MeshData loop_subdivide_without_limit(const std::vector<Vec3>& positions, const std::vector<int>& indices, int levels) {
  Level m = control_mesh(positions, indices, levels);
  m = subdivide_levels(std::move(m), levels);
  build_topology(m);  // the checks, when levels is 0
  return to_mesh(m, {});
}

MeshData loop_subdivide(const std::vector<Vec3>& positions, const std::vector<int>& indices, int levels) {
  Level m = control_mesh(positions, indices, levels);
  m = subdivide_levels(std::move(m), levels);
  const Topology t = build_topology(m);
  Level limit = m;
  for (size_t v = 0; v < m.p.size(); ++v) {
    const std::vector<int> ring = t.ring(int(v));
    const size_t n = ring.size();
    // A boundary is the cubic B-spline of its polygon (the crease rule 1/8, 3/4, 1/8 is that
    // spline's subdivision), whose limit mask is 1/6, 2/3, 1/6. pbrt-v4 uses 1/5, 3/5, 1/5,
    // which is not where the boundary converges (tests/shapes/loop_subdivision_test.cpp).
    limit.p[v] = t.boundary[v] ? boundary_rule(m, int(v), ring, 1.0 / 6.0)
                               : one_ring_rule(m, int(v), ring, 1.0 / (double(n) + 3.0 / (8.0 * beta(n))));
  }
  Topology lt = t;
  lt.m = &limit;
  std::vector<DVec3> normals(limit.p.size());
  for (size_t v = 0; v < limit.p.size(); ++v) normals[v] = limit_normal(limit, lt, int(v));
  return to_mesh(limit, normals);
}

}  // namespace eyetrace
