// The plane's texture: the project's butterfly (datasets/textures/butterfly.png), a
// procedural stand-in when the datasets are not found, and a loader for PNG and JPEG.
#pragma once

#include <QImage>
#include <QString>

namespace oflab {

// A 320 x 256 RGBA image (aspect 1.25, like the default plane's 1 x 0.8): a light checkerboard
// of 32-texel cells with a stylised butterfly whose antennae and larger fore-wings mark
// the texture's top, so mirroring and rotation are visible.
QImage procedural_texture();

// The bundled butterfly (analysis/formats/datasets.h: default_texture_path, $OFLAB_DATASETS
// honoured), or procedural_texture() when it cannot be read.
QImage default_texture();

// Reads a PNG or JPEG as RGBA, after analysis/formats/image_io.h's check_image_file (the
// signature and the size limits). Returns a null image and sets *error to one line naming
// the file when it cannot be read or is refused.
QImage load_texture_image(const QString& path, QString* error);

}  // namespace oflab
