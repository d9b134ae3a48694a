#include "mesh/surface_boundary.hpp"

#include <numeric>
#include <vector>

namespace sf {
namespace {

/// The representative of node v's set (path halving).
int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

SurfaceBoundary surface_boundary(const TriangleSurface& surface) {
  SurfaceBoundary b;
  const TriConn& tri = surface.triangles();
  const TriConn& neighbours = surface.triangle_neighbours();
  const Matrix3X& x = surface.nodes();
  // Union-find over the nodes of free edges: each set of joined free edges is one boundary.
  std::vector<int> parent(surface.num_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> on_boundary(surface.num_nodes(), 0);
  for (int t = 0; t < surface.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      if (neighbours(a, t) >= 0) {
        continue;
      }
      const int u = tri(a, t), v = tri((a + 1) % 3, t);
      ++b.free_edges;
      b.length += (x.col(v) - x.col(u)).norm();
      on_boundary[u] = on_boundary[v] = 1;
      parent[find_root(parent, u)] = find_root(parent, v);
    }
  }
  for (int v = 0; v < surface.num_nodes(); ++v) {
    b.boundaries += on_boundary[v] && find_root(parent, v) == v ? 1 : 0;
  }
  return b;
}

}  // namespace sf
