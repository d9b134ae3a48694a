#pragma once
// A rigid tool surface made of triangles, held in its REFERENCE configuration.
//
// A tool moves rigidly by a translation u(t); a query point x is mapped into the reference frame
// as x - u(t), so nothing here is rebuilt while the tool moves.
#include <string>
#include <vector>

#include "core/types.hpp"

namespace sf {

/// Triangulated rigid tool surface in its reference configuration (mm).
///
/// Invariants (established by the constructor and kept by `flip_triangles`): every triangle has
/// three distinct, in-range node indices and a non-zero area; `triangle_normals()` are the unit
/// normals (x2 - x1) x (x3 - x1) / |...| of the triangles as stored; `node_normals()` are the
/// normalised arithmetic mean of the normals of the triangles sharing each node (the averaged
/// nodal normal of Wawrzyk & Kowalczyk, "Modified contact search algorithm for sheet metal
/// forming"); a node used by no triangle has a zero nodal normal, and so has a node whose
/// triangle normals cancel exactly (a knife edge).
class TriangleSurface {
 public:
  TriangleSurface() = default;
  /// Builds the surface and its derived data. Throws InputError naming `name` and the triangle
  /// for an out-of-range or repeated node index, or a degenerate (zero-area) triangle.
  TriangleSurface(std::string name, Matrix3X nodes, TriConn triangles);

  const std::string& name() const { return name_; }
  int num_nodes() const { return static_cast<int>(nodes_.cols()); }
  int num_triangles() const { return static_cast<int>(triangles_.cols()); }
  /// Node coordinates, mm, column per node (reference configuration).
  const Matrix3X& nodes() const { return nodes_; }
  /// Node indices of each triangle, column per triangle.
  const TriConn& triangles() const { return triangles_; }
  /// Unit normal of each triangle, column per triangle.
  const Matrix3X& triangle_normals() const { return triangle_normals_; }
  /// Averaged unit normal of each node (see the class comment), column per node.
  const Matrix3X& node_normals() const { return node_normals_; }
  /// Node -> triangle adjacency (CSR): the triangles of node i are
  /// node_triangles()[node_triangle_offsets()[i] .. node_triangle_offsets()[i+1]), ascending.
  const std::vector<int>& node_triangle_offsets() const { return node_triangle_offsets_; }
  const std::vector<int>& node_triangles() const { return node_triangles_; }
  /// Edge adjacency: triangle_neighbours()(a, t) is the triangle across edge a of triangle t,
  /// edge a running from its local node a to node (a + 1) % 3 (edge 0: x1 -> x2, edge 1:
  /// x2 -> x3, edge 2: x3 -> x1), so edge a is opposite local node (a + 2) % 3. -1 on a boundary
  /// edge and on an edge shared by more than two triangles (no unique neighbour).
  const TriConn& triangle_neighbours() const { return triangle_neighbours_; }

  /// Reverses the orientation of every triangle t with flip[t] != 0 (swaps its 2nd and 3rd
  /// node) and updates the normals and the edge adjacency (whose edge numbering follows the
  /// node order). `flip` has one entry per triangle.
  void flip_triangles(const std::vector<char>& flip);

 private:
  void compute_normals();
  void compute_neighbours();

  std::string name_;
  Matrix3X nodes_;
  TriConn triangles_;
  Matrix3X triangle_normals_;
  Matrix3X node_normals_;
  std::vector<int> node_triangle_offsets_;
  std::vector<int> node_triangles_;
  TriConn triangle_neighbours_;
};

/// What orient_surface found and did (for the tool's report).
struct SurfaceOrientation {
  int components = 0;       ///< connected components (triangles joined across shared edges)
  int made_consistent = 0;  ///< triangles turned over to agree with their component's orientation
  int turned_to_blank = 0;  ///< triangles turned over with their component to face the blank
};

/// Orients a tool surface for contact with a blank:
///  1. makes the orientation consistent across every shared edge, connected component by
///     connected component (breadth-first propagation);
///  2. flips each component so that its normals face the blank: every blank node (a strided
///     sample of at most 2000) votes for the side it lies on, counted only when its closest point
///     on that component lies inside a triangle (a face hit), with weight 1 / distance; a
///     component with no face hit at all falls back to the votes of all closest points.
/// Throws InputError naming the tool when a component is not orientable (a Moebius-like strip:
/// the position where the orientation meets itself reversed) or an edge is shared by more than
/// two triangles (how many such edges, and the end points of the first few, mm). A component
/// without votes (no blank nodes) is left as it is.
SurfaceOrientation orient_surface(TriangleSurface& surface, const Matrix3X& blank_nodes);

}  // namespace sf
