#include "gui/lessons.h"

namespace oflab {
namespace {

Lesson flow_of_a_plane() {
  Lesson lesson;
  lesson.name = "flow-of-a-plane";
  lesson.title = "The flow of a plane";
  lesson.caption =
      "The flow of a plane. The butterfly turns and moves away from us; each arrow shows how "
      "fast that point of the image moves (pixels per second). For a plane this flow is "
      "exactly quadratic: choose 'Exact - homography flow' under Show and it vanishes. "
      "Choose 'Exact - affine flow' to see what an affine warp misses.";
  lesson.view = "flow";
  lesson.scene = default_demo_scene();
  lesson.flow.part = FlowPart::Full;
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
  lesson.basis = BasisKind::Planar;
  lesson.play_basis = true;
  return lesson;
}

}  // namespace

const std::vector<Lesson>& lessons() {
  static const std::vector<Lesson> all = {flow_of_a_plane(), basis_deformations()};
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
