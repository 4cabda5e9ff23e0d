#include "app/lessons.h"

namespace oflab {
namespace {

Lesson flow_of_a_plane() {
  Lesson lesson;
  lesson.name = "flow-of-a-plane";
  lesson.title = "The flow of a plane";
  lesson.caption =
      "The flow of a plane. The butterfly circles, turns and tilts in front of us; each arrow "
      "shows how fast that point of the image moves (pixels per second). For a plane this flow is "
      "exactly quadratic: choose 'Exact - homography flow' under Show and it vanishes. "
      "Choose 'Exact - affine flow' to see what an affine warp misses.";
  lesson.view = "flow";
  lesson.scene = default_demo_scene();
  lesson.flow.part = FlowPart::kFull;
  lesson.flow.arrows = true;
  lesson.flow.streamlines = true;
  return lesson;
}

Lesson basis_deformations() {
  Lesson lesson;
  lesson.name = "basis-deformations";
  lesson.title = "The basis deformations";
  lesson.caption =
      "Basis deformations. Each tile deforms a square by one term of the flow alone. In the "
      "planar basis a moving plane excites only two of the six second-order terms, px and "
      "py: the grey tiles stay zero whatever the motion. Switch to the raw Taylor terms (four "
      "second-order terms move) and to Waxman-Ullman (all six do).";
  lesson.view = "basis";
  lesson.scene = default_demo_scene();
  lesson.basis = BasisKind::kPlanar;
  lesson.play_basis = true;
  return lesson;
}

Lesson affine_vs_perspective() {
  Lesson lesson;
  lesson.name = "affine-vs-perspective";
  lesson.title = "Affine vs perspective";
  lesson.caption =
      "Affine vs perspective. The butterfly tips towards us and away, close to us, so its near "
      "edge looks much longer than its far edge. Three panels play the same frames at once: affine "
      "warps, perspective warps and the exact projection; under each approximation, its "
      "difference from the exact frame. An affine warp keeps parallel edges parallel: watch "
      "its heat map light up while the perspective panel's stays dark.";
  lesson.view = "animation";
  lesson.scene = default_demo_scene();
  lesson.animation_kind = "script";
  lesson.animation_name = "swing";
  lesson.mode = &reuse_policy("affine");
  lesson.display = PanelDisplay::kComparison;
  lesson.play_motion = true;
  return lesson;
}

Lesson why_errors_accumulate() {
  Lesson lesson;
  lesson.name = "why-errors-accumulate";
  lesson.title = "Why errors accumulate";
  lesson.caption =
      "Why errors accumulate. Each cheap update neglects part of the motion, and the neglected "
      "parts add up frame after frame: in the bottom charts each level's error climbs until "
      "it would cross its dashed threshold, and then the engine pays for a better update and "
      "the error drops. Play the motion and click a frame to ask why that level was chosen.";
  lesson.view = "analysis";
  lesson.scene = default_demo_scene();
  lesson.play_motion = true;
  return lesson;
}

Lesson occlusion() {
  Lesson lesson;
  lesson.name = "occlusion";
  lesson.title = "Occlusion";
  lesson.caption =
      "Occlusion. Five textured squares, partly behind one another, seen by a viewer moving "
      "sideways. Every square is its own layer with its own engine and level (outline "
      "colour); the layers are composited back to front, so the warps never have to handle "
      "hidden parts. Squares wholly covered are not updated at all.";
  lesson.view = "animation";
  lesson.scene = default_demo_scene();
  lesson.animation_kind = "scene";
  lesson.animation_name = "five-semi-occluded";
  lesson.animation_viewer = "translate";
  lesson.play_motion = true;
  return lesson;
}

}  // namespace

Lesson flow_vs_talisman() {
  Lesson lesson;
  lesson.name = "flow-vs-talisman";
  lesson.title = "Optic flow against Talisman";
  lesson.caption =
      "Optic flow against Talisman. The butterfly loops through space; three panels play the "
      "same frames: optic flow (perspective), Talisman (the layer as last rendered, moved by "
      "the affine warp that best fits its corners) and the exact projection. Talisman warps "
      "every frame and re-renders whenever its fit misses a corner by a pixel; optic flow "
      "moves the layer for free while it can and pays for a perspective warp when it must. "
      "Compare the costs under the panels.";
  lesson.view = "animation";
  lesson.scene = default_demo_scene();
  lesson.animation_kind = "script";
  lesson.animation_name = "loop";
  lesson.mode = &reuse_policy("perspective");
  lesson.display = PanelDisplay::kComparison;
  lesson.compared = {&reuse_policy("perspective"), &reuse_policy("talisman")};
  lesson.play_motion = true;
  return lesson;
}

Lesson when_reuse_pays() {
  Lesson lesson;
  lesson.name = "when-reuse-pays";
  lesson.title = "When does reuse pay?";
  lesson.caption =
      "When does reuse pay? A walk down a street of facade impostors (about 1 200 lit, "
      "depth-tested faces each) and shaded brick walls (lit per sample). Two panels play the "
      "same frames: optic flow (perspective) and re-rendering every frame, beside the exact "
      "projection. A re-render here costs tens of warps per pixel, so every frame the engine "
      "moves a layer instead of redrawing it is time saved; with a bitmap, a re-render is one "
      "warp and reuse saves nothing. Compare the times under the panels, and watch the turn: "
      "the warped walls keep stale shading.";
  lesson.view = "animation";
  lesson.scene = default_demo_scene();
  lesson.animation_kind = "scene";
  lesson.animation_name = "street";
  lesson.animation_viewer = "walk";
  lesson.mode = &reuse_policy("perspective");
  lesson.display = PanelDisplay::kComparison;
  lesson.compared = {&reuse_policy("perspective"), &reuse_policy("rerender")};
  lesson.play_motion = true;
  return lesson;
}

const std::vector<Lesson>& lessons() {
  static const std::vector<Lesson> all = {
      flow_of_a_plane(), basis_deformations(), affine_vs_perspective(), why_errors_accumulate(),
      occlusion(),       flow_vs_talisman(),   when_reuse_pays()};
  return all;
}

const Lesson* find_lesson(const std::string& name) {
  for (const Lesson& lesson : lessons()) {
    if (lesson.name == name) return &lesson;
  }
  return nullptr;
}

std::string lesson_names() {
  std::string names;
  for (const Lesson& lesson : lessons()) names += (names.empty() ? "" : ", ") + lesson.name;
  return names;
}

}  // namespace oflab
