#include "views/explorer_panel.h"

#include <QDoubleSpinBox>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>

#include "adapters/painted_text.h"
#include "basis/basis_catalog.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/explorer_pictures.h"
#include "views/image_canvas.h"
#include "views/slider_spin.h"

namespace oflab {
namespace {

constexpr int kSliderSteps = 100;  // slider positions on each side of zero

QString vector_text(const Vec3& v) {
  return QStringLiteral("(%1, %2, %3)")
      .arg(v.x, 0, 'f', 2)
      .arg(v.y, 0, 'f', 2)
      .arg(v.z, 0, 'f', 2)
      .replace(QStringLiteral("-0.00"), QStringLiteral("0.00"));
}

}  // namespace

ExplorerPanel::ExplorerPanel(WindowModel* window, QWidget* parent)
    : QObject(parent), window_(window), theme_(view_theme(false)) {
  dials_ = make_dials(parent);
  deformation_ = new ImageCanvas(parent);
  deformation_->setObjectName(QStringLiteral("explorer_deformation"));
  worlds_ = make_worlds(parent);
  timer_ = new QTimer(this);
  timer_->setInterval(int(std::lround(kFutureFrameSeconds * 1000.0)));
  connect(timer_, &QTimer::timeout, this, &ExplorerPanel::step_futures);
  connect(deformation_, &ImageCanvas::resized, this, [this] {
    if (deformation_->isVisible()) paint();
  });
  connect(futures_, &ImageCanvas::resized, this, [this] {
    if (futures_->isVisible()) paint_futures();
  });
  connect(sketch_, &ImageCanvas::resized, this, [this] {
    if (sketch_->isVisible()) paint();
  });
}

ExplorerPanel::~ExplorerPanel() = default;

QWidget* ExplorerPanel::make_dials(QWidget* parent) {
  auto* box = new QWidget(parent);
  box->setObjectName(QStringLiteral("explorer_dials"));
  auto* column = new QVBoxLayout(box);
  column->setContentsMargins(0, 0, 0, 0);
  auto* title = new QLabel(tr("<b>Dial the eight planar terms</b>"), box);
  title->setObjectName(QStringLiteral("explorer_title"));
  title->setWordWrap(true);
  column->addWidget(title);
  // The dials close together, so that the solutions under them fit a 768-pixel window.
  auto* dials = new QVBoxLayout;
  dials->setSpacing(1);
  column->addLayout(dials);
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const ExplorerTerm& term = explorer_terms()[size_t(k)];
    const double span = term.slider_span;
    auto* slider = new SliderSpin(QString::fromLatin1(term.key), -span, span, span / kSliderSteps,
                                  term.decimals, QStringLiteral(" ") + order_unit(term.order), box);
    slider->setObjectName(QStringLiteral("explorer_") + term.key);
    slider->set_description(QString::fromLatin1(term.description));
    connect(slider, &SliderSpin::edited, this, [this, k](double value) {
      if (!window_->set_explorer_term(k, value)) refresh(true);  // show the kept value again
    });
    sliders_of_[size_t(k)] = slider;
    dials->addWidget(slider);
  }
  auto* buttons = new QHBoxLayout;
  auto* zero = new QPushButton(tr("All zero"), box);
  zero->setObjectName(QStringLiteral("explorer_zero"));
  zero->setToolTip(tr("Set every term to zero: no flow"));
  auto* from_scene = new QPushButton(tr("From the scene"), box);
  from_scene->setObjectName(QStringLiteral("explorer_from_scene"));
  from_scene->setToolTip(tr("The terms of the scene panel's plane and motion now"));
  buttons->addWidget(zero);
  buttons->addWidget(from_scene);
  column->addLayout(buttons);
  solutions_ = new QLabel(box);
  solutions_->setObjectName(QStringLiteral("explorer_solutions"));
  solutions_->setWordWrap(true);
  solutions_->setTextFormat(Qt::RichText);
  column->addSpacing(6);
  column->addWidget(solutions_);
  column->addStretch(1);
  connect(zero, &QPushButton::clicked, this,
          [this] { window_->set_explorer_terms(ExplorerTerms{}); });
  connect(from_scene, &QPushButton::clicked, this, [this] {
    const SceneModel& scene = *window_->scene();
    window_->set_explorer_terms(explorer_terms_of(planar_flow_coefficients(
        scene.scene().camera, scene.current_pose(), scene.current_motion())));
  });
  return box;
}

QWidget* ExplorerPanel::make_worlds(QWidget* parent) {
  auto* box = new QWidget(parent);
  box->setObjectName(QStringLiteral("explorer_worlds"));
  auto* column = new QVBoxLayout(box);
  column->setContentsMargins(0, 0, 0, 0);
  sketch_ = new ImageCanvas(box);
  sketch_->setObjectName(QStringLiteral("explorer_planes"));
  play_ = new QPushButton(tr("Play both solutions forward for 1 s"), box);
  play_->setObjectName(QStringLiteral("explorer_play_futures"));
  play_->setToolTip(
      tr("Move each solution's plane with its own motion, 30 frames, and chart "
         "how far apart their images are"));
  futures_ = new ImageCanvas(box);
  futures_->setObjectName(QStringLiteral("explorer_futures"));
  futures_line_ = new QLabel(box);
  futures_line_->setObjectName(QStringLiteral("explorer_futures_line"));
  futures_line_->setWordWrap(true);
  futures_->setToolTip(
      tr("Above: the image under solution A and under solution B, the other's outline "
         "dashed (when there is room). Below left: the corner that parts most, its path "
         "under each, magnified. Below right: how far apart the images are, per frame."));
  column->addWidget(sketch_, 2);
  column->addWidget(play_);
  column->addWidget(futures_, 3);
  column->addWidget(futures_line_);
  connect(play_, &QPushButton::clicked, this, &ExplorerPanel::play_futures);
  return box;
}

void ExplorerPanel::refresh(bool visible) {
  const ExplorerTerms& terms = window_->explorer_terms();
  for (int k = 0; k < kExplorerTermCount; ++k) sliders_of_[size_t(k)]->set_value(terms[size_t(k)]);
  solved_ = false;
  if (visible) {
    solve();
    paint();
  }
}

void ExplorerPanel::solve() {
  result_ = explore(window_->explorer_terms(), window_->scene()->scene().camera);
  timer_->stop();
  futures_playing_ = false;
  futures_frame_ = result_.futures_played ? result_.futures.frames_played : 0;
  solutions_->setText(solutions_text());
  futures_line_->setText(futures_text());
  play_->setEnabled(result_.futures_played);
  solved_ = true;
}

QString ExplorerPanel::solutions_text() const {
  const InverseFlowSolutions& r = result_.inverse;
  QString html = QStringLiteral("<p><b>%1</b></p>")
                     .arg(QString::fromStdString(explorer_case_text(r)).toHtmlEscaped());
  if (r.solutions.empty()) return html;
  // The solutions side by side, a quantity per row: half the height of one after the other,
  // so that both fit the dials' column under the sliders.
  const QString names[2] = {tr("Solution A"), tr("Solution B")};
  const size_t count = std::min<size_t>(r.solutions.size(), 2);
  const auto row = [&](const QString& name,
                       const std::function<QString(const PlanarMotionSolution&)>& value) {
    QString cells = QStringLiteral("<tr><td>%1&nbsp;&nbsp;</td>").arg(name);
    for (size_t i = 0; i < count; ++i) {
      cells += QStringLiteral("<td>%1&nbsp;&nbsp;</td>").arg(value(r.solutions[i]));
    }
    return cells + QStringLiteral("</tr>");
  };
  html += QStringLiteral("<table cellspacing=0><tr><td></td>");
  for (size_t i = 0; i < count; ++i) html += QStringLiteral("<td><b>%1</b></td>").arg(names[i]);
  html +=
      QStringLiteral("</tr>") +
      row(tr("normal N"),
          [](const PlanarMotionSolution& s) {
            return s.normal_known ? vector_text(s.normal) : tr("any");
          }) +
      row(tr("facing"),
          [](const PlanarMotionSolution& s) {
            return QString::fromStdString(explorer_facing_text(s));
          }) +
      row(tr("V/d, 1/s"), [](const PlanarMotionSolution& s) { return vector_text(s.v_over_d); }) +
      row(tr("Omega, rad/s"), [](const PlanarMotionSolution& s) { return vector_text(s.omega); });
  html += QStringLiteral("</table>");
  html += QStringLiteral("<p>%1</p>")
              .arg(tr("Left out, behind the eye: %1 mirror image(s). d, the plane's distance, "
                      "is never known: only V/d.")
                       .arg(r.dropped_behind));
  return html;
}

QString ExplorerPanel::futures_text() const {
  if (!result_.futures_played) {
    return tr("Nothing to play: %1.").arg(QString::fromStdString(result_.futures_note));
  }
  const FutureSeparation& f = result_.futures;
  const QString now = tr("Frame %1 of %2: the images are %3 px apart.")
                          .arg(futures_frame_)
                          .arg(f.frames_played)
                          .arg(f.corner_distance_px[size_t(futures_frame_)], 0, 'f', 3);
  const QString first =
      tr("After one frame %1 px; over 1 px first at frame %2.")
          .arg(f.corner_distance_px.size() > 1 ? f.corner_distance_px[1] : 0.0, 0, 'f', 3)
          .arg(f.first_frame_apart < 0 ? tr("none") : QString::number(f.first_frame_apart));
  return now + QStringLiteral(" ") + first;
}

void ExplorerPanel::play_futures() {
  if (!result_.futures_played) return;
  futures_frame_ = 0;
  futures_playing_ = true;
  if (!external_clock_) timer_->start();
  paint_futures();
}

void ExplorerPanel::step_futures() {
  if (!futures_playing_) return;
  futures_frame_ = std::min(futures_frame_ + 1, result_.futures.frames_played);
  if (futures_frame_ >= result_.futures.frames_played) {
    futures_playing_ = false;
    timer_->stop();
  }
  paint_futures();
}

void ExplorerPanel::set_external_clock(bool on) {
  external_clock_ = on;
  if (on) timer_->stop();
  if (!on && futures_playing_) timer_->start();
}

// Room for each slider's name and its field's longest value with the unit, in the theme's
// control font (a projector's large text must not be cut).
void ExplorerPanel::fit_sliders() {
  QFont font = dials_->font();
  if (theme_.control_font_px > 0) font.setPixelSize(theme_.control_font_px);
  const QFontMetrics metrics(font);
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const ExplorerTerm& term = explorer_terms()[size_t(k)];
    SliderSpin* slider = sliders_of_[size_t(k)];
    const QString widest = QString::number(-term.slider_span, 'f', term.decimals) +
                           QStringLiteral(" ") + order_unit(term.order);
    slider->spin_box()->setMinimumWidth(metrics.horizontalAdvance(widest) + 2 * metrics.height());
    if (auto* name = slider->findChild<QLabel*>()) {
      name->setMinimumWidth(metrics.horizontalAdvance(QStringLiteral("rotation")) + 8);
    }
  }
  // The column is as wide as its widest slider needs with a short slider, whatever the
  // solutions' text (the layout does not jump while a slider moves); the deformation and the
  // worlds take the rest.
  int widest = 0;
  for (SliderSpin* slider : sliders_of_) {
    widest = std::max(widest, slider->spin_box()->minimumWidth());
  }
  dials_->setFixedWidth(metrics.horizontalAdvance(QStringLiteral("rotation")) + widest +
                        9 * metrics.height());
}

void ExplorerPanel::paint() {
  if (!solved_) solve();
  const Mat3 deformation = explorer_deformation(window_->explorer_terms());
  deformation_->set_image(paint_explorer_deformation(window_->scene()->texture(), deformation,
                                                     window_->scene()->scene().camera,
                                                     deformation_->size(), theme_));
  sketch_->set_image(paint_explorer_solutions(result_, sketch_->size(), theme_));
  paint_futures();
}

double ExplorerPanel::deformation_fill() const {
  if (!deformation_->isVisible()) return 0.0;
  return explorer_deformation_fill(explorer_deformation(window_->explorer_terms()),
                                   window_->scene()->scene().camera, deformation_->size(), theme_);
}

void ExplorerPanel::paint_futures() {
  futures_->set_image(paint_explorer_futures(result_, futures_frame_, window_->scene()->texture(),
                                             window_->scene()->scene().camera, futures_->size(),
                                             theme_));
  futures_line_->setText(futures_text());
}

std::vector<QString> ExplorerPanel::text_problems() const {
  std::vector<QString> problems;
  const auto add = [&problems](const QString& where, const std::vector<QString>& found) {
    for (const QString& problem : found) problems.push_back(where + QStringLiteral(": ") + problem);
  };
  const auto painted = [&](ImageCanvas* canvas, const std::function<void(QPainter&)>& draw) {
    if (!canvas->isVisible() || canvas->size().isEmpty()) return;
    add(canvas->objectName(),
        oflab::text_problems(record_painted_text(canvas->size(), draw), canvas->size()));
  };
  painted(sketch_,
          [this](QPainter& p) { draw_explorer_solutions(p, result_, sketch_->size(), theme_); });
  painted(futures_, [this](QPainter& p) {
    draw_explorer_futures(p, result_, futures_frame_, window_->scene()->texture(),
                          window_->scene()->scene().camera, futures_->size(), theme_);
  });
  for (QWidget* column : {dials_, worlds_}) {
    for (QWidget* part : column->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
      if (!part->isVisible()) continue;
      const auto* label = qobject_cast<QLabel*>(part);
      const int needed = label && label->wordWrap() ? label->heightForWidth(label->width()) : 0;
      if (part->height() < needed) {
        problems.push_back(QStringLiteral("%1: %2 px high, its text needs %3")
                               .arg(part->objectName())
                               .arg(part->height())
                               .arg(needed));
      } else if (part->geometry().bottom() >= column->height()) {
        problems.push_back(QStringLiteral("%1: reaches past its column (bottom %2 of %3 px)")
                               .arg(part->objectName())
                               .arg(part->geometry().bottom())
                               .arg(column->height()));
      }
    }
  }
  return problems;
}

void ExplorerPanel::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  fit_sliders();
  for (ImageCanvas* canvas : {deformation_, sketch_, futures_}) {
    canvas->set_background(
        QColor::fromRgbF(theme.background[0], theme.background[1], theme.background[2]));
  }
  if (solved_) paint();
}

}  // namespace oflab
