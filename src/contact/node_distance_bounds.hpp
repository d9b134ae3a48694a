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
//
// A node within the cutoff may still be provably out of contact: a front bound, taken where the
// node was found apart, keeps its own anchor f and two slacks (side and gap, mm; see
// docs/contact.md, "Nodes near a tool but out of contact"). With delta = |p - f|, the node at p
// with half thickness h is out of contact while delta < side and delta + h < gap.
#include <algorithm>

#include "core/types.hpp"

namespace sf {

/// Anchors and slacks of every blank node against one tool. No allocation after `resize`.
class NodeDistanceBounds {
 public:
  /// `node_count` nodes, every bound unknown (the first query bounds the node).
  void resize(int node_count) {
    anchor_.setZero(3, node_count);
    slack_.setZero(node_count);
    front_anchor_.setZero(3, node_count);
    front_side_.setZero(node_count);
    front_gap_.setZero(node_count);
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
  /// The front bounds as they are (anchors mm, side and gap slacks mm), for a checkpoint.
  Matrix3X& front_anchors() { return front_anchor_; }
  const Matrix3X& front_anchors() const { return front_anchor_; }
  VectorX& front_sides() { return front_side_; }
  const VectorX& front_sides() const { return front_side_; }
  VectorX& front_gaps() { return front_gap_; }
  const VectorX& front_gaps() const { return front_gap_; }

  /// Node i found the tool within the cutoff.
  void set_within_cutoff(int i) { slack_[i] = -1.0; }

  /// Whether node i at p (reference frame, mm) with half thickness h (mm) is provably out of
  /// contact by its front bound: a few flops.
  bool provably_apart(int i, const Vec3& p, double h) const {
    const double m = std::min(front_side_[i], front_gap_[i] - h);
    return m > 0 && (p - front_anchor_.col(i)).squaredNorm() < m * m;
  }
  /// Whether a front bound of node i at p is worth computing: always, unless the last attempt
  /// failed less than `retry` (mm) from p.
  bool may_bound_front(int i, const Vec3& p, double retry) const {
    return front_side_[i] >= 0 || (p - front_anchor_.col(i)).squaredNorm() >= retry * retry;
  }
  /// Node i was found in contact: its front bound is dropped (a skipped node must have the
  /// zero normal and stick forces its last, apart, call left; a press writes them).
  void clear_front(int i) {
    front_side_[i] = 0.0;
    front_gap_[i] = 0.0;
  }
  /// Node i's front bound taken at p: its side and gap slacks (mm); side <= 0 (or not a number)
  /// records a failed attempt there.
  void set_front(int i, const Vec3& p, double side, double gap) {
    front_anchor_.col(i) = p;
    const bool holds = side > 0;
    front_side_[i] = holds ? side : -1.0;
    front_gap_[i] = holds ? gap : 0.0;
  }

 private:
  Matrix3X anchor_;  ///< where each bound was taken, reference frame, mm
  VectorX slack_;    ///< mm; > 0 a bound, 0 unknown, < 0 within the cutoff at the last query
  // The front bounds, a shortcut only (a checkpoint keeps them, so that a restart skips the same
  // nodes; the next case's pairs start afresh).
  Matrix3X front_anchor_;  ///< where each front bound was taken (or last failed), mm
  VectorX front_side_;     ///< mm; >= 0 the side slack, < 0 the last attempt failed
  VectorX front_gap_;      ///< mm; the gap slack (delta + h must stay below it)
};

}  // namespace sf
