#pragma once
// Shaft verdicts for a chunk of patches (geometry/shaft.h), shared by the form factors
// (radiosity.cpp: one receiving patch against a chunk of sources) and the final gather (gather.cpp:
// one receiver point against a chunk of emitting patches). The chunks are tiles of one face
// (docs/performance.md, "Visibility: which pairs trace rays").
//
// Without a verdict each patch of the chunk traces five segments (patches.h visible_fraction). A
// verdict for the box that holds every sample point of the chunk's patches stands for all those
// segments at once: `visible` or `hidden` is what each segment would say (the verdicts are proofs),
// so the sums stay the same to the bit. It costs about as much as a dozen segments, so it is
// asked lazily: the first patch that needs visibility traces its own segments, the second asks for
// the chunk. Where the verdict is `partial` (an occluder's edge lies in the shaft) every patch
// traces its segments. Asking again for each half of a partial chunk was measured and does not
// pay: in tests/rooms/tshape 68 % of the halves were partial too, and the run took 8 % more CPU
// than without them (examples/lshape 2 % less; farm-bench -n 3, paired).
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// The lazy verdict of one chunk against one receiver. `classify()` gives the verdict for the
// segments between the receiver and the sample points of the chunk's patches; it is called at most
// once. Inactive (no visibility): every patch is `visible` and nothing is asked.
template <class Classify>
class ChunkVerdict {
 public:
  ChunkVerdict(bool active, Classify classify) : active_(active), classify_(classify) {}

  // The verdict for the next patch of the chunk that needs visibility.
  geometry::Shaft ask() {
    if (!active_) return geometry::Shaft::visible;
    if (++asked_ == 2) verdict_ = classify_();
    return verdict_;
  }

 private:
  bool active_;
  Classify classify_;
  int asked_ = 0;
  geometry::Shaft verdict_ = geometry::Shaft::partial;
};

// The final gather's verdict of one chunk against one receiver point (gather.cpp): asked at the
// first patch that needs visibility, narrowed (geometry/visibility.h classify_within) so that a
// patch of a partial chunk gets its own verdict from the faces the chunk's left undecided
// (partial_visibility.h undecided_patch_integral), a few face tests each. `classify(faces)` gives
// the verdict and fills `faces`; it is called at most once.
template <class Classify>
class NarrowingChunkVerdict {
 public:
  NarrowingChunkVerdict(bool active, Classify classify) : active_(active), classify_(classify) {}

  geometry::Shaft ask() {
    if (!active_) return geometry::Shaft::visible;
    if (!asked_) verdict_ = classify_(faces_), asked_ = true;
    return verdict_;
  }
  // The faces the chunk's verdict left undecided (after ask() said `partial`).
  const geometry::ShaftFaces& faces() const { return faces_; }

 private:
  bool active_;
  Classify classify_;
  bool asked_ = false;
  geometry::Shaft verdict_ = geometry::Shaft::partial;
  geometry::ShaftFaces faces_;
};

}  // namespace luxgrid::calc::indirect
