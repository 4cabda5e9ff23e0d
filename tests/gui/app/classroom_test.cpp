// The window as a teacher uses it: at 1920x1080 in presentation mode no text is smaller than
// kPresentationMinTextPx and no coefficient is elided; the play keys work whatever has
// focus; a value typed while the motion plays applies; Ctrl+N shows the Nth view; every
// control explains itself in a tooltip.
#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QScrollBar>
#include <QSlider>
#include <QStatusBar>
#include <QTabBar>
#include <QTableWidget>

#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/coefficient_table.h"
#include "views/flow_view.h"
#include "views/scene_controls.h"
#include "views/slider_spin.h"
#include "views/view_page.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

using ClassroomTest = WindowTest;

// The controls a user can click or type into, among the widgets visible in the window.
std::vector<QWidget*> visible_controls(QWidget& window) {
  std::vector<QWidget*> controls;
  for (QWidget* w : window.findChildren<QWidget*>()) {
    if (!w->isVisibleTo(&window) || qobject_cast<QScrollBar*>(w)) continue;
    // Parts Qt builds inside a control (a tab bar's scroll arrows, a dock's title buttons)
    // are that control's, not the window's.
    if (qobject_cast<QTabBar*>(w->parentWidget()) || w->inherits("QDockWidgetTitleButton"))
      continue;
    if (qobject_cast<QAbstractButton*>(w) || qobject_cast<QAbstractSlider*>(w) ||
        qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w)) {
      controls.push_back(w);
    }
  }
  return controls;
}

// Text-bearing widgets: labels, controls, tables, tab bars.
bool shows_text(QWidget* w) {
  return qobject_cast<QLabel*>(w) || qobject_cast<QAbstractButton*>(w) ||
         qobject_cast<QComboBox*>(w) || qobject_cast<QAbstractSpinBox*>(w) ||
         qobject_cast<QTableWidget*>(w) || qobject_cast<QTabBar*>(w) ||
         qobject_cast<QLineEdit*>(w) || qobject_cast<QHeaderView*>(w) ||
         qobject_cast<QDockWidget*>(w) || qobject_cast<QStatusBar*>(w) ||
         qobject_cast<QMenuBar*>(w);
}

void show_at_projector_size(MainWindow& window) {
  window.resize(1920, 1080);
  window.model()->set_presentation(true);
  QApplication::processEvents();
}

TEST_F(ClassroomTest, PresentationTextIsAtLeastEighteenPixelsOnEveryView) {
  show_at_projector_size(window());
  for (const QString& name : window().view_names()) {
    ASSERT_TRUE(window().show_view(name));
    window().play_frames(2);
    window().view(name)->render_image();
    const double drawn = window().view(name)->smallest_text_px();
    if (drawn > 0.0) {
      EXPECT_GE(drawn, kPresentationMinTextPx) << name.toStdString();
    }
    for (QWidget* w : window().findChildren<QWidget*>()) {
      if (!w->isVisibleTo(&window()) || !shows_text(w)) continue;
      EXPECT_GE(QFontInfo(w->font()).pixelSize(), kPresentationMinTextPx)
          << name.toStdString() << ": " << w->metaObject()->className() << " "
          << w->objectName().toStdString();
    }
  }
  window().model()->set_presentation(
      false);  // the application's fonts are global: leave them normal
}

// A smaller window scales presentation mode's sizes: the smaller of width / 1920 and height
// / 1080, within 0.6 .. 1 (computed here independently for each window), the theme's fonts
// rounded from the 1920 x 1080 sizes.
TEST(PresentationScale, IsTheSmallerRatioToA1080pWindowWithinItsLimits) {
  EXPECT_DOUBLE_EQ(presentation_scale(1920, 1080), 1.0);
  EXPECT_DOUBLE_EQ(presentation_scale(3840, 2160), 1.0);  // never larger
  EXPECT_DOUBLE_EQ(presentation_scale(1366, 768), 768.0 / 1080.0);
  EXPECT_DOUBLE_EQ(presentation_scale(1280, 1024), 1280.0 / 1920.0);  // the width limits
  EXPECT_DOUBLE_EQ(presentation_scale(800, 600), kPresentationMinScale);
  const ViewTheme small = view_theme(true, 768.0 / 1080.0);
  EXPECT_EQ(small.font_size, 16);   // 22 x 0.711 = 15.6
  EXPECT_EQ(small.label_size, 14);  // 20 x 0.711 = 14.2
  EXPECT_EQ(small.control_font_px, 14);
  EXPECT_EQ(presentation_min_text_px(768.0 / 1080.0), 12);                   // 18 x 0.711 = 12.8
  EXPECT_EQ(view_theme(false, 0.5).font_size, view_theme(false).font_size);  // normal look
}

// On a 1366 x 768 projector the window's controls and the views' texts are presentation mode's
// sizes scaled by 0.711: no text under presentation_min_text_px, the controls' font 14 px; the
// control: back at 1920 x 1080 the controls' font is 20 px again.
TEST_F(ClassroomTest, PresentationTextScalesWithASmallerWindow) {
  window().resize(1366, 768);
  window().model()->set_presentation(true);
  QApplication::processEvents();
  const double scale = window().theme().scale;
  EXPECT_NEAR(scale, 768.0 / 1080.0, 1e-9);
  EXPECT_EQ(QFontInfo(QApplication::font()).pixelSize(), 14);
  for (const char* name : {"flow", "basis", "analysis"}) {
    ASSERT_TRUE(window().show_view(QString::fromLatin1(name)));
    window().view(QString::fromLatin1(name))->render_image();
    EXPECT_GE(window().view(QString::fromLatin1(name))->smallest_text_px(),
              presentation_min_text_px(scale))
        << name;
  }
  show_at_projector_size(window());
  EXPECT_EQ(QFontInfo(QApplication::font()).pixelSize(), 20) << "the control: 1920 x 1080";
  window().model()->set_presentation(false);
}

// The scrub bar's groove shows in both looks: beyond the handle (at the first frame, the
// whole groove is the unplayed part) some pixel of the bar's middle line stands at least 40
// lightness levels apart from the window's colour.
TEST_F(ClassroomTest, ScrubGrooveShowsInBothLooks) {
  window().resize(1600, 900);
  for (bool presentation : {false, true}) {
    window().model()->set_presentation(presentation);
    window().model()->scene()->set_frame(0);
    QApplication::processEvents();
    auto* scrub = window().findChild<QSlider*>(QStringLiteral("scrub_slider"));
    ASSERT_NE(scrub, nullptr);
    const QImage bar = scrub->grab().toImage();
    const int window_lightness = scrub->palette().color(QPalette::Window).lightness();
    int apart = 0;
    for (int x = bar.width() / 2; x < bar.width() - 4; ++x) {
      apart = std::max(
          apart, std::abs(QColor(bar.pixel(x, bar.height() / 2)).lightness() - window_lightness));
    }
    EXPECT_GE(apart, 40) << (presentation ? "presentation" : "normal");
  }
  window().model()->set_presentation(false);
}

TEST_F(ClassroomTest, NormalLookKeepsItsSmallerText) {
  // The scale is the theme's: the normal look is not presentation-sized.
  EXPECT_LT(view_page<FlowView>(window(), "flow")->smallest_text_px(), kPresentationMinTextPx);
  EXPECT_LT(window().view("analysis")->smallest_text_px(), kPresentationMinTextPx);
}

TEST_F(ClassroomTest, CoefficientTableElidesNothingAtProjectorSize) {
  show_at_projector_size(window());
  window().show_view("flow");
  // Frames where the planar terms take long values (negative, many digits).
  for (int frame : {0, 7, 20}) {
    window().model()->scene()->set_frame(frame);
    QApplication::processEvents();
    auto* table = view_page<FlowView>(window(), "flow")
                      ->findChild<QTableWidget*>(QStringLiteral("coefficient_table"));
    ASSERT_NE(table, nullptr);
    const QFontMetrics fm(table->font());
    int columns = 0;
    for (int col = 0; col < table->columnCount(); ++col) columns += table->columnWidth(col);
    EXPECT_GE(table->viewport()->width(), columns) << "the table is cut on the right";
    for (int row = 0; row < table->rowCount(); ++row) {
      for (int col = 0; col < table->columnCount(); ++col) {
        const QString text = table->item(row, col)->text();
        // The item's margins take a few pixels either side of the text.
        EXPECT_LE(fm.horizontalAdvance(text) + 6, table->columnWidth(col))
            << "row " << row << " column " << col << ": " << text.toStdString();
      }
    }
  }
  window().model()->set_presentation(false);
}

TEST_F(ClassroomTest, EveryVisibleControlHasATooltip) {
  for (const QString& name : window().view_names()) {
    ASSERT_TRUE(window().show_view(name));
    QApplication::processEvents();
    for (QWidget* w : visible_controls(window())) {
      EXPECT_FALSE(w->toolTip().trimmed().isEmpty())
          << name.toStdString() << ": " << w->metaObject()->className() << " '"
          << w->objectName().toStdString() << "'";
    }
  }
}

TEST_F(ClassroomTest, EveryCoefficientSaysWhatItIsAndItsUnit) {
  auto* table = view_page<FlowView>(window(), "flow")
                    ->findChild<QTableWidget*>(QStringLiteral("coefficient_table"));
  ASSERT_NE(table, nullptr);
  for (int row = 0; row < table->rowCount(); ++row) {
    const QString tip = table->item(row, 1)->toolTip();
    EXPECT_TRUE(tip.startsWith(table->item(row, 0)->text() + ": ")) << tip.toStdString();
    EXPECT_TRUE(tip.endsWith(table->item(row, 2)->text())) << tip.toStdString();
  }
}

TEST_F(ClassroomTest, ControlNumberKeysShowTheViewsInTableOrder) {
  QApplication::setActiveWindow(&window());
  const QStringList names = window().view_names();
  for (int i = names.size() - 1; i >= 0; --i) {
    QTest::keyClick(&window(), Qt::Key(Qt::Key_1 + i), Qt::ControlModifier);
    EXPECT_EQ(window().current_view_name(), names.at(i));
  }
}

TEST_F(ClassroomTest, PlayKeysWorkWhateverHasFocus) {
  QApplication::setActiveWindow(&window());
  SliderSpin* turn = window().scene_controls()->control(QStringLiteral("turn"));
  auto* part =
      view_page<FlowView>(window(), "flow")->findChild<QComboBox*>(QStringLiteral("flow_part"));
  for (QWidget* focus : {static_cast<QWidget*>(turn->slider()), static_cast<QWidget*>(part),
                         static_cast<QWidget*>(turn->spin_box())}) {
    focus->setFocus();
    QApplication::processEvents();
    const double turn_before = turn->value();
    const int part_before = part->currentIndex();
    window().model()->scene()->set_frame(5);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Right);
    EXPECT_EQ(window().model()->scene()->frame(), 6) << focus->metaObject()->className();
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Left);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Left);
    EXPECT_EQ(window().model()->scene()->frame(), 4);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_End);
    EXPECT_EQ(window().model()->scene()->frame(), window().model()->scene()->loop_frames() - 1);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Home);
    EXPECT_EQ(window().model()->scene()->frame(), 0);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    EXPECT_TRUE(window().model()->playing());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    EXPECT_FALSE(window().model()->playing());
    EXPECT_EQ(turn->value(), turn_before) << "the keys went to the control";
    EXPECT_EQ(part->currentIndex(), part_before);
  }
}

// Types `text` into a number field and presses Enter, as a user would.
void type_and_enter(QDoubleSpinBox* field, const QString& text) {
  field->setFocus();
  QApplication::processEvents();
  QLineEdit* edit = field->findChild<QLineEdit*>();
  edit->selectAll();
  QTest::keyClicks(QApplication::focusWidget(), text);
  QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
  QApplication::processEvents();
}

TEST_F(ClassroomTest, EnterAppliesTheValueAndSpaceThenPlays) {
  QApplication::setActiveWindow(&window());
  SliderSpin* vx = window().scene_controls()->control(QStringLiteral("velocity_x"));
  type_and_enter(vx->spin_box(), QStringLiteral("0.5"));
  EXPECT_DOUBLE_EQ(window().model()->scene()->scene().motion.velocity.x, 0.5);
  QWidget* focus = QApplication::focusWidget();
  ASSERT_NE(focus, nullptr);
  EXPECT_TRUE(focus == window().current_view() || window().current_view()->isAncestorOf(focus))
      << focus->metaObject()->className();
  QTest::keyClick(focus, Qt::Key_Space);
  EXPECT_TRUE(window().model()->playing());
  EXPECT_DOUBLE_EQ(vx->value(), 0.5);
  EXPECT_TRUE(vx->spin_box()->text().startsWith(QStringLiteral("0.50")))
      << vx->spin_box()->text().toStdString();
  window().model()->set_playing(false);
}

TEST_F(ClassroomTest, ValuesTypedWhilePlayingApply) {
  QApplication::setActiveWindow(&window());
  window().model()->set_playing(true);
  SliderSpin* vy = window().scene_controls()->control(QStringLiteral("velocity_y"));
  QDoubleSpinBox* field = vy->spin_box();
  field->setFocus();
  field->findChild<QLineEdit*>()->selectAll();
  QTest::keyClicks(QApplication::focusWidget(), QStringLiteral("0.7"));
  // Frames go by while the user types: the typed text must survive them.
  for (int i = 0; i < 5; ++i) window().model()->scene()->advance(1);
  QApplication::processEvents();
  EXPECT_TRUE(field->text().startsWith(QStringLiteral("0.7"))) << field->text().toStdString();
  QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
  QApplication::processEvents();
  EXPECT_DOUBLE_EQ(window().model()->scene()->scene().motion.velocity.y, 0.7);
  EXPECT_TRUE(window().model()->playing());
  window().model()->set_playing(false);
}

// With a multi-plane scene playing, the scene panel's single-plane controls do nothing for
// the animation and analysis views (nor for the scene-shifting view's own scene): they are
// disabled there, with a note saying what plays; on the flow and basis views they apply.
TEST_F(ClassroomTest, ScenePanelControlsAreDisabledWhereTheyDoNotApply) {
  SceneControls* panel = window().scene_controls();
  QLabel* note = panel->findChild<QLabel*>("scene_panel_note");
  ASSERT_NE(note, nullptr);
  window().show_view("animation");
  EXPECT_TRUE(panel->control("turn")->isEnabled());  // the demo plays the panel's plane
  EXPECT_FALSE(note->isVisibleTo(panel));
  ASSERT_TRUE(window().model()->animation()->set_source({"scene", "four-cubes", "circle"}));
  for (const char* view : {"animation", "analysis", "slices"}) {
    window().show_view(view);
    EXPECT_FALSE(panel->control("turn")->isEnabled()) << view;
    EXPECT_FALSE(panel->control("velocity_x")->isEnabled()) << view;
    EXPECT_FALSE(panel->control("focal")->isEnabled()) << view;
    EXPECT_TRUE(note->isVisibleTo(panel)) << view;
  }
  window().show_view("animation");
  EXPECT_TRUE(panel->note().contains("four-cubes")) << panel->note().toStdString();
  for (const char* view : {"flow", "basis"}) {
    window().show_view(view);
    EXPECT_TRUE(panel->control("turn")->isEnabled()) << view;
    EXPECT_FALSE(note->isVisibleTo(panel)) << view;
  }
  window().show_view("animation");
  ASSERT_TRUE(window().model()->animation()->set_source({"plane", "", ""}));
  EXPECT_TRUE(panel->control("turn")->isEnabled());
}

}  // namespace
}  // namespace oflab::test
