#include "app/app_theme.h"

#include <QApplication>
#include <QFont>
#include <QPalette>
#include <QStyle>
#include <vector>

#include "adapters/view_theme.h"

namespace oflab {
namespace {

QPalette dark_palette() {
  QPalette p;
  const QColor window(45, 47, 52), base(30, 32, 36), text(225, 225, 225);
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, window);
  p.setColor(QPalette::ToolTipBase, base);
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, window);
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::Highlight, QColor(0, 114, 178));  // Okabe-Ito blue
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::Disabled, QPalette::Text, QColor(110, 110, 110));
  p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(110, 110, 110));
  p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(110, 110, 110));
  return p;
}

QPalette light_palette() {
  QPalette p = QApplication::style()->standardPalette();
  p.setColor(QPalette::Window, QColor(250, 250, 247));
  p.setColor(QPalette::Base, Qt::white);
  p.setColor(QPalette::Disabled, QPalette::Text, QColor(160, 160, 160));
  return p;
}

// Widgets the platform gives a font of their own (smaller, often), which the application
// font does not replace.
constexpr const char* kOwnFontClasses[] = {"QHeaderView", "QDockWidget", "QStatusBar",
                                           "QMenuBar",    "QMenu",       "QTabBar",
                                           "QToolButton", "QTipLabel",   "QMessageBox"};

}  // namespace

void apply_app_theme(const ViewTheme& theme) {
  static const QFont base_font = QApplication::font();
  static const std::vector<QFont> base_class_fonts = [] {
    std::vector<QFont> fonts;
    for (const char* name : kOwnFontClasses) fonts.push_back(QApplication::font(name));
    return fonts;
  }();
  if (QApplication::style()->objectName().compare(QLatin1String("fusion"), Qt::CaseInsensitive)) {
    QApplication::setStyle(QStringLiteral("Fusion"));  // the application owns the style
  }
  QApplication::setPalette(theme.presentation ? light_palette() : dark_palette());
  QFont font = base_font;
  if (theme.control_font_px > 0) font.setPixelSize(theme.control_font_px);
  QApplication::setFont(font);
  for (size_t i = 0; i < base_class_fonts.size(); ++i) {
    QApplication::setFont(theme.control_font_px > 0 ? font : base_class_fonts[i],
                          kOwnFontClasses[i]);
  }
}

}  // namespace oflab
