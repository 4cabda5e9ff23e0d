// The scene engine's walk front to back (core/scene/scene_animator.h, steps 3 and 4): the hidden
// test of each polygon against what is already in front, the waves of layer updates that run at
// once on the worker threads, and the record of each update, drawn fragment and occluder in
// the walk's order. The rest of the frame loop is scene_animator.cpp.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "engine/wall_clock.h"
#include "image/thread_pool.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

using Clock = WallClock;

// The intersection of two convex polygons: `a` clipped by every edge of `b`.
ConvexPolygon intersection(ConvexPolygon a, const ConvexPolygon& b) {
  const std::vector<Vec2>& v = b.vertices();
  for (std::size_t k = 0; k < v.size() && !a.empty(); ++k) {
    const Vec2 e = v[next_vertex(k, v.size())] - v[k];
    a = clip_to_half_plane(a, Vec3(-e.y, e.x, e.y * v[k].x - e.x * v[k].y));
  }
  return b.empty() ? ConvexPolygon() : a;
}

// The time greedy list scheduling takes to run costs[first..] (dearest first) on `threads`
// threads, each next update on the thread free first: how for_each_band hands out bands.
double makespan(const std::vector<double>& costs, std::size_t first, int threads) {
  std::vector<double> load(static_cast<std::size_t>(std::max(threads, 1)), 0.0);
  for (std::size_t k = first; k < costs.size(); ++k) {
    *std::min_element(load.begin(), load.end()) += costs[k];
  }
  return *std::max_element(load.begin(), load.end());
}

}  // namespace

void SceneEngine::update_front_to_back(const ViewerPose& current, AnimationFrame& report) {
  const std::vector<BspFragment>& fragments = bsp_.fragments();
  fragment_drawn_.assign(fragments.size(), 0);
  fragment_regions_.resize(fragments.size());
  occlusion_.clear(camera_.width, camera_.height);
  if (settings_.engine.warp_area == WarpArea::kVisible) {
    shown_pixels_.fill(camera_.width, camera_.height);
  }
  wave_.clear();
  // Front to back: decide visibility against what is already in front, queue the update,
  // and once the wave has run let each drawn fragment hide what lies behind it.
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    const int f = *it;
    const int p = fragments[f].polygon;
    if (statuses_[p] == PolygonStatus::kBackFacing ||
        statuses_[p] == PolygonStatus::kOutsideFrustum) {
      continue;
    }
    const bool update = !states_[p]->updated;
    if (update) {
      const auto tv = Clock::now();
      const ConvexPolygon candidate =
          settings_.skip_hidden ? hidden_candidate(f, current) : ConvexPolygon();
      const bool blocked = !settings_.waves || wave_blocks(p, candidate);
      report.visibility_ms += ms_since(tv);
      if (blocked) run_wave(current, report);
      if (settings_.skip_hidden) {
        const auto th = Clock::now();
        const bool hidden = occlusion_.covers(candidate, settings_.candidate_margin_px);
        report.visibility_ms += ms_since(th);
        if (hidden) continue;
      }
    }
    wave_.push_back(wave_entry(f, update));
  }
  run_wave(current, report);
}

SceneEngine::WaveEntry SceneEngine::wave_entry(int fragment, bool update) {
  const int p = bsp_.fragments()[fragment].polygon;
  PolygonLayer& s = *states_[p];
  WaveEntry e;
  e.fragment = fragment;
  e.update = update;
  if (update) {
    s.updated = true;
    s.in_wave = true;
  }
  e.occludes = settings_.skip_hidden && s.opaque;
  if (!e.occludes) return e;
  if (!s.in_wave) {
    // Updated in an earlier wave: its layer is known.
    const PlacedLayer* shown = s.shown(statuses_[p]);
    e.occludes = shown && !shown->layer.empty();
    if (e.occludes) {
      e.reach = translated(shown->layer.polygon, shown->offset_x, shown->offset_y);
    }
    return e;
  }
  // Its layer is still to come: its exact image grown by what the shown layer may stray
  // from it (the errors its level leaves, this frame's and the last frame's, and rounding).
  double stray = 8.0;
  if (!s.needs_clipping && s.candidates.kind == LayerCandidates::Kind::kChoice) {
    const int level = static_cast<int>(s.allocated);
    if (level < kTermCount) stray += 2.0 * s.candidates.error[level];
    if (s.live && std::isfinite(s.report.measured_error_px)) {
      stray += 2.0 * s.report.measured_error_px;
    }
  }
  e.reach = dilated(polygon_region(p), stray);
  return e;
}

// True when the wave must run before polygon p is tested and queued: its hidden test's
// candidate would be covered, or the test gives up, were every layer of the wave as wide as
// it may reach (an occluder only ever covers more, so a candidate left uncovered then is
// uncovered by the layers the wave will draw too); or both are clipped texture renders
// sharing the scratch texture they draw from.
bool SceneEngine::wave_blocks(int polygon, const ConvexPolygon& candidate) const {
  const auto uses_scratch = [&](int p) {
    return states_[p]->needs_clipping && !content_is_lit(polygon_content(p));
  };
  const bool scratch = uses_scratch(polygon);
  const int texture = scene_.polygons[polygon].texture;
  std::vector<ConvexPolygon> reaches;
  for (const WaveEntry& e : wave_) {
    const int p = bsp_.fragments()[e.fragment].polygon;
    if (e.update && scratch && uses_scratch(p) && scene_.polygons[p].texture == texture) {
      return true;
    }
    if (e.occludes) reaches.push_back(e.reach);
  }
  if (candidate.empty() || reaches.empty()) return false;
  bool gave_up = false;
  const bool covered =
      occlusion_.covers(candidate, settings_.candidate_margin_px, reaches, &gave_up);
  return covered || gave_up;
}

void SceneEngine::run_wave(const ViewerPose& current, AnimationFrame& report) {
  std::vector<int> polygons;
  for (const WaveEntry& e : wave_) {
    if (e.update) polygons.push_back(bsp_.fragments()[e.fragment].polygon);
  }
  std::vector<PolygonUpdate> updates(polygons.size());
  const int count = static_cast<int>(polygons.size());
  if (count > 0) ++report.update_waves;
  if (count == 1) {
    update_polygon(polygons[0], current, updates[0]);  // its own loops use the threads
  } else if (count > 1) {
    // The dearest first, so that the threads finish together (each update writes only its
    // own polygon's state and record, so the order changes no byte).
    std::vector<int> order(polygons.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> cost(polygons.size());
    for (std::size_t k = 0; k < polygons.size(); ++k) cost[k] = update_cost(polygons[k]);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
    std::vector<double> sorted(polygons.size());
    for (std::size_t k = 0; k < sorted.size(); ++k) sorted[k] = cost[order[k]];
    // The dearest update first alone, every thread in its own loops, then the rest side by
    // side, when that ends sooner than all side by side: a layer far dearer than the others
    // (a near facade re-rendered while the street turns) kept one thread busy while the other
    // waited. Either way each update writes the same bytes. Its own loops are taken to gain
    // three quarters of a thread per thread added (a lit render's bands are not all equal).
    const int threads = worker_threads();
    const double alone_time = sorted[0] / (1.0 + 0.75 * (threads - 1));
    int alone = 0;
    if (threads > 1 && alone_time + makespan(sorted, 1, threads) < makespan(sorted, 0, threads)) {
      update_polygon(polygons[order[0]], current, updates[order[0]]);
      alone = 1;
    }
    for_each_band(count - alone, 1, [&](int, int begin, int end) {
      for (int k = begin + alone; k < end + alone; ++k)
        update_polygon(polygons[order[k]], current, updates[order[k]]);
    });
  }
  std::size_t next = 0;
  for (const WaveEntry& e : wave_) {
    if (e.update) {
      states_[polygons[next]]->in_wave = false;
      record_update(updates[next++], report);
    }
    draw_fragment(e.fragment, current, report);
  }
  wave_.clear();
}

double SceneEngine::update_cost(int polygon) {
  const PolygonLayer& s = *states_[polygon];
  const bool lit = content_is_lit(polygon_content(polygon));
  if (s.needs_clipping)
    return static_cast<double>(box_pixels(polygon_region(polygon))) * (lit ? 8 : 1);
  const Level level =
      s.candidates.kind == LayerCandidates::Kind::kChoice ? s.allocated : Level::kRerender;
  const double pixels = static_cast<double>(s.candidates.pixels[static_cast<int>(level)]);
  return level == Level::kRerender && lit ? 8.0 * pixels : pixels;
}

void SceneEngine::draw_fragment(int fragment, const ViewerPose& current, AnimationFrame& report) {
  const int p = bsp_.fragments()[fragment].polygon;
  PolygonLayer& s = *states_[p];
  const PlacedLayer* shown = s.shown(statuses_[p]);
  if (!shown || shown->layer.empty()) return;
  fragment_drawn_[fragment] = 1;
  if (!s.whole) fragment_regions_[fragment] = fragment_region(fragment, current);
  if (settings_.skip_hidden && s.opaque) {
    const auto tv = Clock::now();
    add_occluder(fragment, *shown);
    report.visibility_ms += ms_since(tv);
  }
}

void SceneEngine::add_occluder(int fragment, const PlacedLayer& shown) {
  // What this fragment certainly paints opaque hides whatever is tested after it.
  const PolygonLayer& s = *states_[bsp_.fragments()[fragment].polygon];
  const bool visible_only = settings_.engine.warp_area == WarpArea::kVisible;
  if (s.whole) {
    occlusion_.add_occluder(shown.layer.polygon, settings_.occluder_inset_px,
                            Vec2(shown.offset_x, shown.offset_y));
    if (visible_only) {
      shown_pixels_.remove_centres_inside(
          eroded(translated(shown.layer.polygon, shown.offset_x, shown.offset_y),
                 settings_.occluder_inset_px));
    }
  } else {
    const ConvexPolygon drawn =
        intersection(translated(shown.layer.polygon, shown.offset_x, shown.offset_y),
                     fragment_regions_[fragment]);
    occlusion_.add_occluder(drawn, settings_.occluder_inset_px);
    if (visible_only) {
      shown_pixels_.remove_centres_inside(eroded(drawn, settings_.occluder_inset_px));
    }
  }
}

}  // namespace oflab
