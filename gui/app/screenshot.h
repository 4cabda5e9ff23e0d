// Capturing what the window shows, VTK content included, and saving it.
#pragma once

#include <QImage>
#include <QString>

class QWidget;

namespace oflab {

// The widget as drawn on screen: QWidget::grab for the Qt parts, with the framebuffer of
// every visible QVTKOpenGLNativeWidget inside it painted over its place (so the result
// never shows a black hole where a VTK view is, whatever the Qt version grabs).
QImage grab_with_vtk(QWidget* root);

// Writes the image as PNG. Returns false and sets *error to one line naming the file when
// it cannot be written.
bool save_png(const QImage& image, const QString& path, QString* error);

// True when the image has more than one colour (a rendered view is never uniform).
bool has_content(const QImage& image);

}  // namespace oflab
