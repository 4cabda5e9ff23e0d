// Capturing what the window shows and saving it.
#pragma once

#include <QImage>
#include <QString>

class QWidget;

namespace oflab {

// The widget as drawn on screen: QWidget::grab, as RGB32. The window holds no
// QVTKOpenGLNativeWidget any more (whose framebuffer a grab could miss), so the grab is the
// whole picture; the name is kept for its callers.
QImage grab_with_vtk(QWidget* root);

// Writes the image as PNG. Returns false and sets *error to one line naming the file when
// it cannot be written.
bool save_png(const QImage& image, const QString& path, QString* error);

// True when the image has more than one colour (a rendered view is never uniform).
bool has_content(const QImage& image);

}  // namespace oflab
