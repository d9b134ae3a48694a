#pragma once
// Per blank node, how far it may move relative to a tool before it could come within the contact
// search's cutoff: the state behind skipping the nodes far from a tool (the re-sort criterion of
// production explicit codes, made exact).
//
// A bound taken at anchor a (tool reference frame) says d(a) >= L, d the distance to the tool.
// Distance is 1-Lipschitz, so at p: d(p) >= L - |p - a|. With slack = L - w(cutoff) - rounding
// (w the search's tie window), |p - a| < slack proves d(p) > w(cutoff): the search would find
// nothing within the cutoff, so the node exerts no force. |p - a| is the node's displacement
// relative to the tool since the anchor, so both the node's and the tool's motion count.
#include "core/types.hpp"

namespace sf {

/// Anchors and slacks of every blank node against one tool. No allocation after `resize`.
class NodeDistanceBounds {
 public:
  /// `node_count` nodes, every bound unknown (the first query bounds the node).
  void resize(int node_count) {
    anchor_.setZero(3, node_count);
    slack_.setZero(node_count);
  }
  int node_count() const { return static_cast<int>(slack_.size()); }

  /// Whether node i at p (reference frame, mm) provably stays beyond the cutoff: a few flops.
  bool beyond_cutoff(int i, const Vec3& p) const {
    const double s = slack_[i];
    return s > 0 && (p - anchor_.col(i)).squaredNorm() < s * s;
  }
  /// Whether node i had the tool within the cutoff at its last query (then it is searched
  /// first; otherwise it is bounded first).
  bool was_within_cutoff(int i) const { return slack_[i] < 0; }

  /// Node i at p may move `slack` (mm) before it could come within the cutoff (slack <= 0 or
  /// not a number: it may not move at all).
  void set(int i, const Vec3& p, double slack) {
    anchor_.col(i) = p;
    slack_[i] = slack > 0 ? slack : 0.0;
  }
  /// The anchors (mm) and slacks (mm) as they are, for a checkpoint to keep and restore.
  Matrix3X& anchors() { return anchor_; }
  const Matrix3X& anchors() const { return anchor_; }
  VectorX& slacks() { return slack_; }
  const VectorX& slacks() const { return slack_; }

  /// Node i found the tool within the cutoff.
  void set_within_cutoff(int i) { slack_[i] = -1.0; }

 private:
  Matrix3X anchor_;  ///< where each bound was taken, reference frame, mm
  VectorX slack_;    ///< mm; > 0 a bound, 0 unknown, < 0 within the cutoff at the last query
};

}  // namespace sf
