#include "calc/direct_reach.h"

#include <algorithm>
#include <limits>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace luxgrid::calc {

namespace {
// Boxes are compared with this margin, far above the 1 um tolerance of inside_room and the
// occlusion test: a luminaire or face counted in too many zones costs a few tested pairs, one
// counted in too few would lose light.
constexpr double kBoxMargin_m = 1e-3;

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void add(const Box& b) {
    add(b.lo);
    add(b.hi);
  }
  bool touches(const Box& b) const {
    return lo.x <= b.hi.x + kBoxMargin_m && b.lo.x <= hi.x + kBoxMargin_m &&
           lo.y <= b.hi.y + kBoxMargin_m && b.lo.y <= hi.y + kBoxMargin_m &&
           lo.z <= b.hi.z + kBoxMargin_m && b.lo.z <= hi.z + kBoxMargin_m;
  }
  bool contains(const Vec3& p) const { return touches(Box{p, p}); }
};

Box room_box(const Room& room) {
  Box b;
  for (const Vec2& c : room.outline) {
    b.add(Vec3(c.x, c.y, room.floor_z));
    b.add(Vec3(c.x, c.y, room.floor_z + room.height));
  }
  return b;
}

// Every point the opening can emit from: its rectangle (a disk's bounding rectangle) in the
// luminaire's z = 0 plane, widened by its luminous height both ways so either convention of a
// box or cylinder is inside.
Box opening_box(const Luminaire& l) {
  Box b;
  b.add(l.pose.position);
  const auto& o = l.opening;
  for (const double sx : {-0.5, 0.5}) {
    for (const double sy : {-0.5, 0.5}) {
      for (const double sz : {-1.0, 1.0}) {
        b.add(l.pose.position + l.pose.rotation * Vec3(sx * o.length, sy * o.width, sz * o.height));
      }
    }
  }
  return b;
}

Box face_box(const geometry::Face& f) {
  Box b;
  for (const Vec3& c : f.corners) b.add(c);
  return b;
}

constexpr int32_t kOutside = -1;  // in no room
constexpr int32_t kSeveral = -2;  // in more than one room (on a shared wall)
}  // namespace

DirectReach::DirectReach(const Scene& scene, std::shared_ptr<const geometry::Visibility> visibility)
    : scene_(scene), visibility_(std::move(visibility)), per_room_(scene.rooms.size() > 1) {
  ReachZone everything;
  everything.luminaires.resize(scene.luminaires.size());
  for (uint32_t k = 0; k < everything.luminaires.size(); ++k) everything.luminaires[k] = k;
  everything.visibility = visibility_;
  zones_.push_back(std::move(everything));
  zone_rooms_.emplace_back();
}

uint32_t DirectReach::zone_for_rooms(const std::vector<uint32_t>& rooms) {
  for (uint32_t z = 1; z < zone_rooms_.size(); ++z) {
    if (zone_rooms_[z] == rooms) return z;
  }
  // The luminaires whose opening touches any of the rooms, in the scene's order (so sums over
  // them add in the same order as sums over every luminaire), and the box every segment from
  // one of them to a point of these rooms lies in.
  ReachZone zone;
  Box reach;
  for (const uint32_t r : rooms) reach.add(room_box(scene_.rooms[r]));
  for (uint32_t k = 0; k < scene_.luminaires.size(); ++k) {
    const Box lum = opening_box(scene_.luminaires[k]);
    const bool lights = std::any_of(rooms.begin(), rooms.end(), [&](uint32_t r) {
      return lum.touches(room_box(scene_.rooms[r]));
    });
    if (!lights) continue;
    zone.luminaires.push_back(k);
    reach.add(lum);
  }
  if (visibility_) {
    // Only faces that touch that box can cross such a segment: the same answers as the whole
    // scene's tree, from a tree of the room's own faces and its neighbours'.
    if (faces_.empty()) faces_ = scene_faces(scene_);
    std::vector<geometry::Face> near;
    for (const auto& f : faces_) {
      if (face_box(f).touches(reach)) near.push_back(f);
    }
    zone.visibility = std::make_shared<const geometry::OcclusionTree>(near);
  }
  zones_.push_back(std::move(zone));
  zone_rooms_.push_back(rooms);
  return static_cast<uint32_t>(zones_.size() - 1);
}

std::vector<uint32_t> DirectReach::zones_of(const geometry::SurfaceGrid& grid) {
  const size_t n = grid.points.size();
  std::vector<uint32_t> zone(n, 0);
  if (!per_room_) return zone;
  std::vector<Box> boxes;
  for (const auto& r : scene_.rooms) boxes.push_back(room_box(r));
  auto rooms_of = [&](const Vec3& p) {
    std::vector<uint32_t> in;
    for (uint32_t r = 0; r < boxes.size(); ++r) {
      if (boxes[r].contains(p) && inside_room(scene_.rooms[r], p)) in.push_back(r);
    }
    return in;
  };
  // Which rooms each point lies in, in parallel: one room, none, or several.
  std::vector<int32_t> key(n, kOutside);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (!grid.active.empty() && !grid.active[i]) continue;  // not calculated: zone 0, unused
      const auto in = rooms_of(grid.points[i]);
      key[i] = in.empty() ? kOutside : in.size() == 1 ? static_cast<int32_t>(in[0]) : kSeveral;
    }
  });
  std::map<int32_t, uint32_t> single;
  for (size_t i = 0; i < n; ++i) {
    if (key[i] == kOutside) continue;
    if (key[i] == kSeveral) {
      zone[i] = zone_for_rooms(rooms_of(grid.points[i]));
      continue;
    }
    auto [it, added] = single.try_emplace(key[i], 0);
    if (added) it->second = zone_for_rooms({static_cast<uint32_t>(key[i])});
    zone[i] = it->second;
  }
  return zone;
}

}  // namespace luxgrid::calc
