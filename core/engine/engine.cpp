// Algorithm 1 for one plane (dissertation section 5.6.1), corrected; see core/engine/engine.h for
// the frames and manual/animation.md for the rules and the errata fixed (22-27). This file is
// the frame's decision: the measure (the flow, the books carried, the exact error each level
// would leave, the levels' costs), the choice, and apply, which hands the chosen level to the
// shown layer's updates (core/engine/layer_updates.cpp).
#include "engine/engine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/wall_clock.h"
#include "flow/homography.h"
#include "flow/reprojection.h"

namespace oflab {
namespace {

using Clock = WallClock;

}  // namespace

PlaneEngine::PlaneEngine(const Camera& camera, Layer texture, const EngineSettings& settings)
    : camera_(camera), texture_(std::move(texture)), settings_(settings) {
  const std::string problem = content_problem(settings_.content);
  if (!problem.empty()) throw std::invalid_argument("content: " + problem);
  const std::string samples = plane_shaded_samples_problem(settings_.content, camera);
  if (!samples.empty()) throw std::invalid_argument("content: " + samples);
  const std::string budget = frame_budget_problem(settings_.budget);
  if (!budget.empty()) throw std::invalid_argument("budget: " + budget);
  keep_pyramid(texture_, texture_mips_);
}

FrameReport PlaneEngine::start(const PlanePose& pose) { return apply(measure_start(pose).choice); }

FrameReport PlaneEngine::advance(const PlanePose& previous, const RigidMotion& motion,
                                 const PlanePose& current) {
  return apply(measure_advance(previous, motion, current).choice);
}

LayerCandidates PlaneEngine::measure_start(const PlanePose& pose) {
  measure(true, nullptr, nullptr, pose);
  return measured_.candidates;
}

LayerCandidates PlaneEngine::measure_advance(const PlanePose& previous, const RigidMotion& motion,
                                             const PlanePose& current) {
  measure(false, &previous, &motion, current);
  return measured_.candidates;
}

void PlaneEngine::measure(bool start, const PlanePose* previous, const RigidMotion* motion,
                          const PlanePose& current) {
  const auto t0 = Clock::now();
  measured_ = Measured{};
  measured_.start = start;
  if (previous) measured_.previous = *previous;
  if (motion) measured_.motion = *motion;
  measured_.current = current;
  try {
    // The flow is measured at the previous pose: it must be a whole, drawable plane.
    const bool flow_usable =
        !start && shown_ && plane_visibility_problem(measured_.previous).empty();
    if (flow_usable && policy().allows_reuse() && frame_pose(current).kind == Framing::kWhole) {
      measure_choice();
    } else {
      measure_fresh(current);
    }
  } catch (const std::exception& refused) {
    // The frame re-renders (apply_after_refusal); its cost is that of a fresh render.
    const std::string refusal = refused.what();
    measured_.candidates = LayerCandidates{};
    try {
      measure_fresh(current);
    } catch (const std::exception&) {
      measured_.candidates = LayerCandidates{};
    }
    measured_.refusal = refusal;
  }
  measured_.ms = ms_since(t0);
}

void PlaneEngine::measure_fresh(const PlanePose& pose) {
  LayerCandidates& c = measured_.candidates;
  c.choice = Level::kRerender;
  const Framing framing = frame_pose(pose);
  if (framing.kind == Framing::kNotShown) {
    c.kind = LayerCandidates::Kind::kNotShown;
    return;
  }
  c.kind = LayerCandidates::Kind::kFresh;
  if (!policy().shares_budget && !policy().spreads_updates) return;
  const ConvexPolygon region = framing.kind == Framing::kClipped
                                   ? project_to_pixels(camera_, framing.clipped)
                                   : transform(texture_.polygon, target_warp(pose));
  c.pixels[static_cast<int>(Level::kRerender)] = box_pixels(region);
  if (!region.empty()) {
    const BoundingBox b = region.bounds();
    c.extent_px = std::hypot(b.x_max - b.x_min, b.y_max - b.y_min);
  }
}

FrameReport PlaneEngine::apply(Level level, bool shown) {
  FrameReport report = apply_frame(level, shown);
  track_expiry(level, report);
  return report;
}

FrameReport PlaneEngine::apply_frame(Level level, bool shown) {
  const auto t0 = Clock::now();
  if (measured_.start) {
    frame_ = 0;
    shown_ = false;
  } else {
    ++frame_;
  }
  std::string refusal = measured_.refusal;
  if (refusal.empty()) {
    try {
      // time_ms covers measuring, deciding, warping and placing; the diagnostics of
      // finish_report (the measured error) run after the clock is read.
      FrameReport report;
      report.frame = frame_;
      apply_measured(level, shown, report);
      report.time_ms = measured_.ms + ms_since(t0);
      report.warp_ms = report.time_ms - report.render_ms;
      finish_report(measured_.current, report);
      return report;
    } catch (const std::exception& refused) {
      refusal = refused.what();
    }
  }
  return apply_after_refusal(refusal, measured_.ms + ms_since(t0));
}

void PlaneEngine::apply_measured(Level level, bool shown, FrameReport& report) {
  switch (measured_.candidates.kind) {
    case LayerCandidates::Kind::kChoice:
      apply_choice(level, report);
      return;
    case LayerCandidates::Kind::kFresh:
      if (!shown) {
        hide("starved: the frame budget could not afford this layer's render", report);
        return;
      }
      break;
    case LayerCandidates::Kind::kNotShown:
      break;
  }
  render_fresh(measured_.current, report);
}

FrameReport PlaneEngine::apply_after_refusal(const std::string& refusal, double spent_ms) {
  // Any refusal (a warp beyond its range, a singular map) becomes a fresh exact render of
  // the frame, or an invisible frame when even that is refused.
  const auto t0 = Clock::now();
  const PlanePose& current = measured_.current;
  FrameReport report;
  report.frame = frame_;
  try {
    render_fresh(current, report);
    report.time_ms = spent_ms + ms_since(t0);
    report.warp_ms = report.time_ms - report.render_ms;
    finish_report(current, report);
    if (report.visible) report.note = "re-rendered after a refusal: " + refusal;
  } catch (const std::exception& again) {
    report = FrameReport{};
    report.frame = frame_;
    hide(std::string("not drawn: ") + again.what(), report);
    report.time_ms = spent_ms + ms_since(t0);
    report.warp_ms = report.time_ms - report.render_ms;
    finish_report(current, report);
  }
  return report;
}

PlaneEngine::Framing PlaneEngine::frame_pose(const PlanePose& pose_in) const {
  const PlanePose pose = sized_pose(pose_in);
  if (texture_.empty()) return {Framing::kNotShown, "not visible: the texture is empty", {}};
  const PoseProblem p = plane_pose_problem(pose);
  // A centre behind the eye or a plane through it is a matter for clipping; anything else
  // (non-finite values, degenerate axes) cannot be drawn at all.
  const bool drawable_axes =
      p.field.empty() || (p.field == "point" && std::isfinite(pose.point.x) &&
                          std::isfinite(pose.point.y) && std::isfinite(pose.point.z));
  if (!drawable_axes) return {Framing::kNotShown, "not visible: " + p.message, {}};
  const Vec3 corner0 = plane_corners(pose)[0];
  const Vec3 to_eye = p.field.empty() ? pose.point : corner0;
  if (std::abs(glm::dot(glm::normalize(pose.normal), glm::normalize(to_eye))) < 1e-3) {
    return {Framing::kNotShown, "not visible: the plane is seen edge-on", {}};
  }
  if (!plane_meets_image(camera_, pose, settings_.near)) {
    bool beyond_near = false;
    for (const Vec3& c : plane_corners(pose)) beyond_near = beyond_near || c.z >= settings_.near;
    return {Framing::kNotShown,
            beyond_near ? "outside the image"
                        : "not visible: wholly nearer than the near plane or behind the eye",
            {}};
  }
  const double gw = settings_.guard_band * camera_.width;
  const double gh = settings_.guard_band * camera_.height;
  ViewPolygon rectangle;
  bool whole = true;
  for (const Vec3& c : plane_corners(pose)) {
    rectangle.points.push_back(c);
    const Vec2 q = c.z > 0.0 ? centred_to_pixel(camera_, project_centred(camera_, c)) : Vec2(0.0);
    whole = whole && c.z >= settings_.near && q.x >= -gw && q.x <= camera_.width + gw &&
            q.y >= -gh && q.y <= camera_.height + gh;
  }
  if (whole) return {};
  rectangle.uv = {Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 1.0), Vec2(0.0, 1.0)};
  Framing f{Framing::kClipped,
            "clipped: the plane reaches in front of the near plane or "
            "beyond the guard band, rendered exactly",
            {}};
  f.clipped = clip_to_frustum(rectangle, view_frustum(camera_, settings_.near, 1.0));
  if (f.clipped.empty()) return {Framing::kNotShown, "outside the image", {}};
  return f;
}

LevelPixels PlaneEngine::level_pixels() const {
  const auto area = [](const Layer& l) {
    return static_cast<std::int64_t>(l.image.width()) * l.image.height();
  };
  const std::int64_t displayed = area(display_.layer);
  return estimate_level_pixels(displayed, cache_.valid ? area(cache_.layer) : displayed);
}

void PlaneEngine::set_frame_plane(const Vec3& m) {
  frame_plane_ = m;
  frame_plane_set_ = true;
}

Vec3 PlaneEngine::render_plane_vector(const PlanePose& sized) const {
  if (policy().frame_plane == FramePlane::kInfinity) return Vec3(0.0);
  if (frame_plane_set_) return frame_plane_;
  const StabilizationPlane& given = settings_.stabilization;
  if (given.automatic || !origin_set_) return plane_vector(sized);
  // The given plane moves with the single plane from its first pose.
  return plane_vector_after(plane_vector_of(given.point, given.normal),
                            rigid_step_between(origin_pose_, sized));
}

Mat3 PlaneEngine::next_model(const PlanarFlowCoefficients& flow, const PlanePose& current,
                             FitFiducials& fit) const {
  fit = fit_;
  if (policy().model == ModelUpdate::kFrameHomography) {
    // One homography for the whole frame since the render: the viewer's rigid step since
    // then and the frame plane kept at the render.
    const RigidStep3 step = rigid_step_between(render_pose_, sized_pose(current));
    return plane_induced_homography(camera_, step, render_plane_) * rendered_warp_;
  }
  if (policy().model == ModelUpdate::kExact) {
    return exact_texture_warp(camera_, sized_pose(current));  // the exact frame-to-frame homography
  }
  if (policy().model == ModelUpdate::kAffineFit) {
    // Talisman: the corners as last rendered, fitted onto their exact projections now.
    const Mat3 exact = exact_texture_warp(camera_, sized_pose(current));
    std::vector<Vec2> rendered, now;
    for (const Vec2& t : texel_corners()) {
      rendered.push_back(apply_homography(rendered_warp_, t));
      now.push_back(apply_homography(exact, t));
    }
    const AffineFit fitted = fit_rendered_polygon(rendered, now);
    fit = fitted.fiducials;
    return fitted.warp * rendered_warp_;
  }
  PlanarFlowCoefficients step = flow;
  if (policy().model == ModelUpdate::kAffineTaylor) step.px = step.py = 0.0;  // affine flow model
  return centred_to_pixel_homography(camera_, taylor_homography(step, 1.0)) * model_;
}

void PlaneEngine::measure_choice() {
  Measured& m = measured_;
  const std::vector<Vec2> corners = displayed_corners_centred();
  m.measures = measure_flow(camera_, m.previous, m.motion, corners);
  const PlanarFlowCoefficients flow =
      reexpand(planar_flow_coefficients(camera_, m.previous, m.motion), m.measures.expansion_point);
  m.flow = m.measures.flow;
  if (policy().books == FlowBooks::kPrinted) {
    m.flow = measure_printed_flow(camera_, m.previous, m.motion, corners);
  }
  if (policy().model == ModelUpdate::kExact) m.flow[3] = 0.0;  // nothing of higher order
  m.model = next_model(flow, m.current, m.fit);
  // Pending errors are image displacements: this frame's motion stretches them by up to
  // the largest singular value of its Jacobian, so they are carried forward scaled by it.
  const Mat3 stretch = mat3_from_rows({1.0 + flow.j11, flow.j12, 0.0},
                                      {flow.j21, 1.0 + flow.j22, 0.0}, {0.0, 0.0, 1.0});
  m.carried = accumulated_;
  for (double& e : m.carried) e *= std::max(1.0, largest_singular_value(stretch));
  // The exact error each level would leave, against the policy's view of the current pose.
  const Mat3 correction = m.model * glm::inverse(displayed_);
  const Vec2 point = centred_to_pixel(camera_, m.measures.expansion_point);
  const Mat3 target = target_warp(m.current);
  for (int l = 0; l < kTermCount; ++l) {
    m.pending[l] =
        corner_distance(warp_after(static_cast<Level>(l), correction, point, m.model), target);
  }
  LayerCandidates& c = m.candidates;
  c.kind = LayerCandidates::Kind::kChoice;
  c.pixels = level_pixels();
  m.since_render = since_render_ + 1;
  c.choice = policy().choose(policy(), {m.flow, m.carried, settings_.thresholds, c.pixels,
                                        m.pending, m.fit, m.since_render, settings_.cadence});
  c.feasible = policy().allowed;
  for (int l = 0; l < kTermCount; ++l) {
    c.error[l] = std::max(neglected_error(m.carried, m.flow, static_cast<Level>(l)), m.pending[l]);
  }
  if (policy().shares_budget) measure_level_costs(correction, point);
  measure_expiry();
}

void PlaneEngine::measure_expiry() {
  Measured& m = measured_;
  LayerCandidates& c = m.candidates;
  if (policy().schedule != Schedule::kThreshold) return;
  const TermArray& thresholds = settings_.thresholds;
  LevelSet reuse{}, free{}, cheap{};
  reuse[highest_reuse_level()] = true;
  free[0] = policy().allowed[0];
  free[1] = policy().allowed[1];
  cheap = free;  // up to affine, when a perspective warp lies above it
  cheap[2] = policy().allowed[2] && highest_reuse_level() > 2;
  m.rerender_slack = level_slack(c.error, thresholds, reuse);
  m.write_slack = level_slack(c.error, thresholds, free);
  m.upgrade_slack = level_slack(c.error, thresholds, cheap);
  c.rerender_expiry = expiry_.rerender.frames_to_expiry_with(m.rerender_slack);
  c.write_expiry = expiry_.write.frames_to_expiry_with(m.write_slack);
  c.upgrade_expiry = cheap[2] ? expiry_.upgrade.frames_to_expiry_with(m.upgrade_slack) : -1;
  c.early_write = Level::kRerender;
  for (Level l : {Level::kAffine, Level::kPerspective}) {
    const int k = static_cast<int>(l);
    if (c.feasible[k] && c.error[k] <= thresholds[k]) {
      c.early_write = l;
      break;
    }
  }
}

void PlaneEngine::track_expiry(Level allocated, FrameReport& report) {
  ExpiryTrack& t = expiry_;
  const Measured& m = measured_;
  const bool choice = m.candidates.kind == LayerCandidates::Kind::kChoice && m.refusal.empty();
  if (m.start) t = ExpiryTrack{};  // frame 0 (again): no life before it
  if (report.visible && report.level != Level::kRerender) {
    if (!choice || policy().schedule != Schedule::kThreshold) return;
    t.rerender.push(m.rerender_slack);
    if (report.level >= Level::kAffine) {
      t.write.clear();
    } else {
      t.write.push(m.write_slack);
    }
    if (report.level >= Level::kPerspective) {
      t.upgrade.clear();
    } else {
      t.upgrade.push(m.upgrade_slack);
    }
    const int ahead = t.rerender.frames_to_expiry();
    report.predicted_expiry = ahead > 0 ? frame_ + ahead : -1;
    t.predicted.push_back(report.predicted_expiry);
    return;
  }
  if (t.live) {
    ExpiryOutcome& o = report.expiry;
    o.ended = true;
    o.by_rule = choice && m.candidates.choice == Level::kRerender;
    o.early = choice && !o.by_rule && allocated == Level::kRerender;
    o.actual = o.by_rule ? frame_ : -1;
    const int made = std::max(t.start + 1, frame_ - kLookaheadHorizon);
    const int index = made - t.start - 1;
    if (index >= 0 && index < static_cast<int>(t.predicted.size())) {
      o.made = made;
      o.predicted = t.predicted[static_cast<std::size_t>(index)];
    }
  }
  t = ExpiryTrack{};
  if (!report.visible) return;
  t.live = true;
  t.start = frame_;
  t.rerender.push(settings_.thresholds[highest_reuse_level()]);  // every error 0 after a render
}

int PlaneEngine::highest_reuse_level() const {
  for (int l = static_cast<int>(Level::kPerspective); l > 0; --l) {
    if (policy().allowed[l]) return l;
  }
  return 0;
}

void PlaneEngine::measure_level_costs(const Mat3& correction, const Vec2& point) {
  // Upper bounds of the pixels each level writes (the boxes of the polygons it warps), and
  // the levels the sampling limit would refuse, as apply_affine and apply_perspective do.
  LayerCandidates& c = measured_.candidates;
  const ConvexPolygon& cache_polygon = cache_.valid ? cache_.layer.polygon : display_.layer.polygon;
  const Mat3 cache_to_display =
      cache_.valid ? cache_.to_display : translation_matrix(display_.offset_x, display_.offset_y);
  const Mat3 affine = affine_part_at(correction, point) * cache_to_display;
  const int a = static_cast<int>(Level::kAffine), p = static_cast<int>(Level::kPerspective);
  c.feasible[a] = c.feasible[a] && largest_singular_value(affine) <= settings_.max_magnification;
  c.pixels[a] = box_pixels(transform(cache_polygon, affine));
  const Vec2 centre = 0.5 * texel_corners()[2];
  const AffinePerspectiveSplit split = split_affine_perspective(
      measured_.model * translation_matrix(centre.x, centre.y), settings_.delta);
  c.feasible[p] =
      c.feasible[p] && largest_singular_value(split.affine) <= settings_.max_magnification;
  const Mat3 texel_to_cache = split.perspective * translation_matrix(-centre.x, -centre.y);
  c.pixels[p] = box_pixels(transform(texture_.polygon, texel_to_cache)) +
                box_pixels(transform(texture_.polygon, measured_.model));
  c.pixels[static_cast<int>(Level::kRerender)] =
      box_pixels(transform(texture_.polygon, target_warp(measured_.current)));
}

void PlaneEngine::apply_choice(Level level, FrameReport& report) {
  const Measured& m = measured_;
  report.flow = m.flow;
  report.carried = m.carried;
  report.pending = m.pending;
  model_ = m.model;
  fit_ = m.fit;
  report.level = level;
  // Erratum 25, corrected: the terms the level neglects accumulate, the ones it handles are
  // caught up with. What the books cannot see (the sub-pixel remainder of a whole-pixel
  // translation, higher orders the first-order bookkeeping misses) is in report.pending.
  for (int k = 0; k < kTermCount; ++k) {
    accumulated_[k] = k >= static_cast<int>(level) ? m.carried[k] + m.flow[k] : 0.0;
  }
  // Talisman's fit is checked against the exact projection each frame: nothing is carried.
  if (policy().model == ModelUpdate::kAffineFit) accumulated_.fill(0.0);
  since_render_ = m.since_render;  // a re-render below resets it
  apply_level(report, m.measures.expansion_point, m.current);
}

}  // namespace oflab
