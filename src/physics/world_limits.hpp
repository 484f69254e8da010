// nbscope physics: the limits that keep a Box2D world from taking the process down, and the
// estimate they are checked with before Box2D is asked to step.
//
// Box2D 2.4.1 makes a b2Contact (~1.7 kB with its solver data, from allocators that never check
// for failure) for every pair of fixtures of different bodies whose fat AABBs (tight AABB + 0.1 m,
// stretched 4x along the last displacement) overlap. Heavily overlapping bodies make that O(N^2):
// 30,000 circles in a 10 x 10 m box ask for ~23M contacts, and Box2D dies inside its allocator
// rather than say so. So before a frame's step the pairs Box2D would make contacts for are counted
// (exactly, without listing them: count_overlapping_boxes) and the step is refused past
// `max_contacts`, or past what the memory this process can get holds (physics/memory_budget.hpp). Crowding also costs time: b2ContactManager::AddPair walks a body's whole contact
// list for every new pair, so a frame costs about the sum over bodies of (contacts per body)^2
// list steps (2,000 circles in that box: 100k contacts, 1.6 s; 4,000: 405k, 50 s); the slow-frame
// note (app/frame_watch.hpp) says so.
//
// Index: bytes_per_contact | CountBox, count_overlapping_boxes | text helpers.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "physics/scene.hpp"  // kDefaultMaxContacts, kMaxWorldCoordinate

namespace nbscope {

// Bytes one Box2D contact costs, as measured (world_limits.cpp says how).
std::int64_t bytes_per_contact();

// An axis-aligned box, closed (touching boxes overlap, as b2TestOverlap).
struct CountBox {
  float x0, y0, x1, y1;
  std::int32_t body;   // boxes of one body never pair
  bool dynamic;        // two boxes neither of whose bodies is dynamic never pair
};

// The number of pairs i < j of `boxes` that overlap, of different bodies, at least one dynamic:
// exactly what a loop over all pairs would count, in O(N log N) time and O(N) memory, without
// listing the pairs (a sweep along x with two Fenwick trees over the y bounds).
std::int64_t count_overlapping_boxes(const std::vector<CountBox>& boxes);

// "14,200,000" (digits grouped in threes).
std::string grouped(std::int64_t n);
// "3.6 GB", "512 MB", "12 kB".
std::string bytes_text(double bytes);

}  // namespace nbscope
