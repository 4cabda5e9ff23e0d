// The scene engine's layer of one polygon (core/scene/scene_animator.h): what the polygon is
// (its outline in world and texture coordinates, its texture's size, whether it is opaque and
// whether the BSP tree split it), its own PlaneEngine (made at its first update), and what
// happened to it in the current frame: its clipped outline and exact region, the measure
// phase's candidates, the level allocated to it and its engine's report. polygon_layer.cpp
// also holds the scene engine's per-polygon steps of a frame (measure, allocate, update).
//
// Units: top-left image pixels for regions and layers, world units for the outline.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "engine/animator.h"
#include "engine/budget.h"
#include "engine/decision.h"
#include "engine/engine.h"
#include "image/polygon.h"
#include "scene/scene.h"
#include "scene/view_culling.h"

namespace oflab {

// What happened to one polygon in a frame.
// kStarved: visible, but the frame budget afforded it no render (core/engine/budget.h): not
// drawn this frame.
enum class PolygonStatus { kBackFacing, kOutsideFrustum, kHidden, kAnimated, kClipped, kStarved };
// The status as a word: "back-facing", "outside-frustum", "hidden", "animated", "clipped",
// "starved".
const char* polygon_status_name(PolygonStatus status);

// One polygon's layer (see above); the scene engine keeps one per polygon, in polygon order.
struct PolygonLayer {
  std::vector<Vec3> world_vertices;  // the outline in world coordinates
  std::vector<Vec2> uv;              // the outline, normalised texture coordinates
  glm::ivec2 texture_size{0, 0};
  bool opaque = false;
  bool whole = true;  // one unsplit fragment in the BSP tree
  std::unique_ptr<PlaneEngine> animator;
  bool live = false;  // the animator shows the previous frame
  // This frame:
  ViewPolygon clipped;         // the outline clipped to the view frustum
  ConvexPolygon exact_region;  // its exact image, top-left pixels (once region_known)
  bool region_known = false;
  bool needs_clipping = false;  // near plane or guard band: render clipped, exactly
  bool updated = false;         // updated, or its update waits in the current wave
  bool in_wave = false;         // its update waits in the current wave
  PlacedLayer clipped_layer;    // the clipped exact render (status kClipped)
  FrameReport report;           // the animator's report (status kAnimated)
  // The measure and allocate phases: what it could do, and what it was given.
  LayerCandidates candidates;
  Level allocated = Level::kRerender;
  bool allocated_shown = true;
  bool starved = false;

  // The layer the polygon shows this frame with `status`: its clipped render, none when
  // starved, else its engine's displayed layer (none before its first update).
  const PlacedLayer* shown(PolygonStatus status) const {
    if (status == PolygonStatus::kClipped) return &clipped_layer;
    if (status == PolygonStatus::kStarved) return nullptr;
    return animator ? &animator->displayed() : nullptr;
  }
};

// What one polygon's update adds to its frame. The scene engine updates the polygons of one
// wave (core/scene/scene_animator.h, step 4) on the worker threads, each into its own
// PolygonUpdate, then adds them to the frame's report and to the budget's ledger in the
// walk's order: the report is the same bytes on any number of threads.
struct PolygonUpdate {
  // Levels, clipped, re-render causes, pixels written, model work, update and render times,
  // and the largest measured and photometric errors of this polygon's update.
  AnimationFrame tally;
  // The ledger's entry (BudgetLedger::applied); `applied` false for none.
  bool applied = false;
  Level level = Level::kRerender;
  double ms = 0.0;
  std::int64_t pixels = 0;
  bool starved = false;

  // Adds the tally to `report`: counts, pixels, work and times summed, errors as maxima.
  void add_to(AnimationFrame& report) const;
};

// One layer per polygon of `scene`, in order, with its outline, texture size and opacity
// (polygon_is_opaque; the rectangles of one texture share one look at it); `whole` is left
// true for the caller to clear for polygons the BSP tree split. Precondition: every polygon's
// texture index is valid (scene_polygon_problem).
std::vector<std::unique_ptr<PolygonLayer>> make_polygon_layers(const Scene& scene);

}  // namespace oflab
