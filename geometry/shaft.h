#pragma once
// Shaft culling for the occlusion test (geometry/occlusion.h): what every segment between two
// convex elements (a luminaire's opening and a receiver point, a patch and a patch, a patch and a
// point) says, decided once for the pair instead of once per segment [HainesWallace1994]. The shaft
// is the convex hull of the two elements; a face that cannot meet it cannot block any of its
// segments, and a face that every segment crosses blocks all of them.
//
// The verdicts are proofs under geometry/face_crossing.h's rule, not estimates: `visible` only
// when no face can cross any segment by the rule (a face whose plane holds one element and has
// the other strictly on one side does not block: the rule shortens each segment by the 1 um end
// allowance), `hidden` only when one face crosses every segment transversally and well inside its
// outline. Everything else is `partial`, and the caller traces its segments one by one. So a
// caller that asks the classification first and the occlusion test for partial pairs gets the
// occlusion test's answer for every segment, bit for bit (docs/performance.md).
//
// Plain doubles, no CGAL, no Embree: a loop over the faces whose boxes meet the shaft's box, a
// side test against each face's plane and, where the shaft crosses it, an overlap test of the
// shaft's section (its convex hull in the face's frame) with the face's outline.
#include <array>
#include <span>
#include <vector>

#include "geometry/box3.h"
#include "geometry/face_crossing.h"
#include "geometry/room.h"
#include "geometry/visibility.h"

namespace luxgrid::geometry {

class ShaftClassifier {
 public:
  explicit ShaftClassifier(const std::vector<Face>& faces);

  // The verdict for every segment from a point of `a` to a point of `b`. Each element is one
  // point, a segment or a planar polygon (any order of corners; not necessarily convex: its
  // convex hull is classified), given by its corners (m, world). Segment ends computed from the
  // corners in double (a quadrature node on an opening, a point lifted off a patch) may lie a few
  // rounding errors (1e-15 m) outside: kShaftSlack_m covers them.
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const;
  // The same verdict over the faces `among` alone (ShaftFaces{}: every face), which must hold
  // every face that may cross a segment (what classifying a shaft that contains this one left
  // undecided): the faces this shaft leaves undecided go to `undecided` when it is `partial`.
  // Numbers are this classifier's (face_of below).
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b, const ShaftFaces& among,
                 ShaftFaces& undecided) const;
  // The index, in the constructor's `faces`, of the classifier's face `k`.
  uint32_t face_of(uint32_t k) const { return faces_[k].face; }

 private:
  struct Candidate {
    uint32_t face = 0;  // its index in the constructor's `faces`
    FaceSheet sheet;
    Box3 box;       // the face's corners, m
    int axis = -1;  // 0..2 when the normal is exactly a coordinate axis (its sign in `sheet`)
  };
  std::vector<Candidate> faces_;
};

// The box [lo, hi] moved by `shift`, as an element for ShaftClassifier::classify: its corners in
// `out`, and their count. A box flat in one axis (the points of one face of a room, whose normal
// is that axis) is a rectangle, its 4 corners in order round it; flat in two axes a segment (2),
// in three a point (1); otherwise its 8 corners (a solid: every pair is a hull edge). A caller
// that groups the sample points of several patches (calc/indirect: a chunk of one face) gets one
// verdict for all the segments from them, as long as every point lies in the box.
size_t box_element(const Vec3& lo, const Vec3& hi, const Vec3& shift, std::array<Vec3, 8>& out);

// How far outside an element a segment's end may lie and still be covered by its verdict, and how
// far from a plane a point counts as on it. Far above double rounding at 1 km (~1e-13 m), far
// below kGrazing_m (1e-9 m), so that two elements both within it of a plane are grazing by the
// rule.
inline constexpr double kShaftSlack_m = 1e-10;

}  // namespace luxgrid::geometry
