#include "generators/tile_texture.h"

#include "generators/butterfly.h"
#include "image/composite.h"

namespace oflab {

Image make_tile_texture() {
  constexpr int kSize = 128;
  constexpr int kBorder = 5;
  Image tile(kSize, kSize);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool border =
          x < kBorder || y < kBorder || x >= kSize - kBorder || y >= kSize - kBorder;
      const bool light = ((x / 16) + (y / 16)) % 2 == 0;
      tile.at(x, y) = border ? Pixel{70, 52, 40, 255}
                             : (light ? Pixel{214, 226, 236, 255} : Pixel{190, 208, 224, 255});
    }
  }
  // The butterfly, centred; its transparent background shows the ground.
  const Image butterfly = make_butterfly(104, 85);
  const int ox = (kSize - butterfly.width()) / 2, oy = (kSize - butterfly.height()) / 2;
  for (int y = 0; y < butterfly.height(); ++y) {
    for (int x = 0; x < butterfly.width(); ++x) {
      tile.at(ox + x, oy + y) = over(butterfly.at(x, y), tile.at(ox + x, oy + y));
    }
  }
  return tile;
}

}  // namespace oflab
