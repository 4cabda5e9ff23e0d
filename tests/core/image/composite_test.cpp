// "Over" compositing against the per-pixel formula, restricted to the layer polygon and
// clipped to the frame.
#include "image/composite.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "image/thread_pool.h"
#include "warp_reference.h"

namespace oflab {
namespace {

// The Porter-Duff formula for premultiplied colour, in double precision. d * k / 255 is
// never a half-integer (255 is odd), so rounding has no ties.
int expected_over(int s, int d, int source_alpha) {
  return s + static_cast<int>(std::floor(d * (255 - source_alpha) / 255.0 + 0.5));
}

TEST(Composite, OverMatchesTheFormulaForEveryAlphaAndDestination) {
  for (int a = 0; a < 256; ++a) {
    for (int d = 0; d < 256; ++d) {
      const auto alpha = static_cast<std::uint8_t>(a);
      const auto source = static_cast<std::uint8_t>(a / 2);
      const auto dest = static_cast<std::uint8_t>(d);
      const Pixel out = over(Pixel{source, 0, alpha, alpha}, Pixel{dest, dest, dest, dest});
      ASSERT_EQ(out.r, expected_over(source, d, a)) << a << " " << d;
      ASSERT_EQ(out.g, expected_over(0, d, a));
      ASSERT_EQ(out.a, expected_over(a, d, a));
    }
  }
}

TEST(Composite, LayerOverFrameMatchesPerPixelFormulaInsideThePolygonOnly) {
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> offset(-30, 50);
  for (int k = 0; k < 100; ++k) {
    const int w = 1 + k % 37;
    const int h = 1 + (k * 7) % 29;
    const Layer layer =
        make_layer(testing::random_image(rng, w, h), testing::random_polygon(rng, w, h));
    const Image before = testing::random_image(rng, 48, 40);
    Image frame = before;
    const int ox = offset(rng);
    const int oy = offset(rng);
    const std::int64_t count = composite_over(frame, layer, ox, oy);
    std::int64_t inside = 0;
    for (int y = 0; y < frame.height(); ++y) {
      for (int x = 0; x < frame.width(); ++x) {
        const int lx = x - ox;
        const int ly = y - oy;
        const Pixel d = before.at(x, y);
        const Pixel got = frame.at(x, y);
        const bool in_image = lx >= 0 && ly >= 0 && lx < w && ly < h;
        const testing::Coverage c =
            in_image ? testing::classify(layer.polygon, Vec2(lx + 0.5, ly + 0.5), 1e-9)
                     : testing::Coverage::kOutside;
        if (c == testing::Coverage::kOutside) {
          ASSERT_EQ(got, d) << x << "," << y;
          continue;
        }
        const Pixel s = layer.image.at(lx, ly);
        const Pixel expected{static_cast<std::uint8_t>(expected_over(s.r, d.r, s.a)),
                             static_cast<std::uint8_t>(expected_over(s.g, d.g, s.a)),
                             static_cast<std::uint8_t>(expected_over(s.b, d.b, s.a)),
                             static_cast<std::uint8_t>(expected_over(s.a, d.a, s.a))};
        if (c == testing::Coverage::kInside) {
          ASSERT_EQ(got, expected) << x << "," << y;
          ++inside;
        } else {
          ASSERT_TRUE(got == expected || got == d);
        }
      }
    }
    EXPECT_GE(count, inside);
  }
}

// Two regions that split the frame along a random line composite every layer pixel
// exactly once: with opaque layer pixels, region by region equals the whole layer, and
// each region's count adds up to the whole count. Regions outside the layer change
// nothing.
TEST(Composite, RegionsThatSplitTheFrameCompositeEachPixelOnce) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const int w = 2 + k % 31;
    const int h = 2 + (k * 5) % 23;
    Image opaque = testing::random_image(rng, w, h);
    for (Pixel& p : opaque.pixels()) p.a = 255;
    const Layer layer = make_layer(opaque, testing::random_polygon(rng, w, h));
    const Image before = testing::random_image(rng, 40, 36);
    const int ox = static_cast<int>(unit(rng) * 20.0) - 5;
    const int oy = static_cast<int>(unit(rng) * 20.0) - 5;
    Image whole = before;
    const std::int64_t whole_count = composite_over(whole, layer, ox, oy);
    // A random line through the frame splits its rectangle into two convex regions.
    const Vec2 a(unit(rng) * 40.0, 0.0);
    const Vec2 b(unit(rng) * 40.0, 36.0);
    const ConvexPolygon frame_box = ConvexPolygon::rectangle(0.0, 0.0, 40.0, 36.0);
    const Vec3 line(b.y - a.y, a.x - b.x, b.x * a.y - a.x * b.y);
    const ConvexPolygon left = clip_to_half_plane(frame_box, line);
    const ConvexPolygon right = clip_to_half_plane(frame_box, -line);
    Image pieces = before;
    const std::int64_t count = composite_over_region(pieces, layer, ox, oy, left) +
                               composite_over_region(pieces, layer, ox, oy, right);
    EXPECT_EQ(count, whole_count) << "case " << k;
    EXPECT_TRUE(pieces.pixels() == whole.pixels()) << "case " << k;
    Image untouched = before;
    EXPECT_EQ(composite_over_region(untouched, layer, ox, oy,
                                    ConvexPolygon::rectangle(100.0, 100.0, 120.0, 120.0)),
              0);
    EXPECT_TRUE(untouched.pixels() == before.pixels());
  }
}

// A frame cleared as it is composited (LazyClear) holds the bytes of a frame cleared first and
// then composited over, whatever its pixels held before start: layers in random order, some
// whole and some restricted to a region, overlapping, apart on a row (the gap is cleared) or
// missing rows (finish clears them), on 1 and on 2 threads. Negative control: without
// finish, the old pixels show where no layer reached.
TEST(Composite, FrameClearedAsItIsCompositedEqualsClearedFirst) {
  std::mt19937 rng(10);
  std::uniform_int_distribution<int> offset(-20, 60);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int garbage_seen = 0;
  for (const int threads : {1, 2}) {
    set_worker_threads(threads);
    for (int k = 0; k < 60; ++k) {
      const int layers = 1 + k % 5;
      Image reference(64, 48);  // cleared first (Pixel{})
      Image lazy = testing::random_image(rng, 64, 48);
      LazyClear clear;
      clear.start(lazy.height());
      std::int64_t reference_count = 0, lazy_count = 0;
      for (int n = 0; n < layers; ++n) {
        const int w = 2 + static_cast<int>(unit(rng) * 40.0);
        const int h = 2 + static_cast<int>(unit(rng) * 30.0);
        Image pixels = testing::random_image(rng, w, h);
        if (n % 2 == 1) {
          for (Pixel& p : pixels.pixels()) p.a = 255;  // opaque, as most scene layers are
        }
        const Layer layer = make_layer(pixels, testing::random_polygon(rng, w, h));
        const int ox = offset(rng), oy = offset(rng);
        if (unit(rng) < 0.5) {
          reference_count += composite_over(reference, layer, ox, oy);
          lazy_count += composite_over(lazy, layer, ox, oy, &clear);
        } else {
          const ConvexPolygon region = testing::random_polygon(rng, 64, 48);
          reference_count += composite_over_region(reference, layer, ox, oy, region);
          lazy_count += composite_over_region(lazy, layer, ox, oy, region, &clear);
        }
      }
      EXPECT_EQ(lazy_count, reference_count) << "case " << k;
      Image unfinished = lazy;
      clear.finish(lazy);
      ASSERT_TRUE(lazy.pixels() == reference.pixels()) << "case " << k << ", threads " << threads;
      garbage_seen += unfinished.pixels() != reference.pixels();
    }
  }
  set_worker_threads(1);
  EXPECT_GT(garbage_seen, 100);  // the control: the old pixels were there to be cleared
}

// Frame after frame on one image (LazyClear::start_on): each frame holds the bytes of a frame
// cleared first and then composited over, although the pixels the last frame left clear are
// not stored again; after other code changed the frame, forget() makes the next frame clear
// it whole, and start_on on another image is start. Controls: a pixel changed behind the
// LazyClear's back, outside every layer, stays changed (the store was skipped), and the
// first frame on a new image, not known, is still right.
TEST(Composite, FramesOnOneImageEqualClearedFirstAndSkipWhatIsKnownClear) {
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> offset(-20, 60);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int threads : {1, 2}) {
    set_worker_threads(threads);
    Image frame = testing::random_image(rng, 64, 48);
    LazyClear clear;
    int skipped = 0;
    for (int k = 0; k < 40; ++k) {
      if (k % 10 == 9) {  // other code draws into the frame: forgotten
        frame = testing::random_image(rng, 64, 48);
        clear.forget();
      }
      // Behind the LazyClear's back: a pixel the last frame left clear, in a row no layer
      // reaches this frame (the last row, which no layer below covers).
      const bool poke = k % 10 == 5;
      if (poke) frame.at(0, 47) = Pixel{1, 2, 3, 4};
      Image reference(64, 48);
      clear.start_on(frame);
      const int layers = 1 + k % 4;
      for (int n = 0; n < layers; ++n) {
        const int w = 2 + static_cast<int>(unit(rng) * 40.0);
        const int h = 2 + static_cast<int>(unit(rng) * 20.0);
        Image pixels = testing::random_image(rng, w, h);
        if (n % 2 == 0) {
          for (Pixel& p : pixels.pixels()) p.a = 255;
        }
        const Layer layer = make_layer(pixels, testing::random_polygon(rng, w, h));
        const int ox = offset(rng), oy = std::min(offset(rng), 40 - h);
        EXPECT_EQ(composite_over(frame, layer, ox, oy, &clear),
                  composite_over(reference, layer, ox, oy));
      }
      clear.finish(frame);
      if (poke) {
        skipped += frame.at(0, 47) == Pixel{1, 2, 3, 4};
        frame.at(0, 47) = Pixel{};
      }
      ASSERT_TRUE(frame.pixels() == reference.pixels()) << "frame " << k << ", threads " << threads;
    }
    EXPECT_EQ(skipped, 4);  // the control: start_on left the known-clear pixel unstored
    // Another image of the same size is not known: cleared whole.
    Image other = testing::random_image(rng, 64, 48);
    clear.start_on(other);
    clear.finish(other);
    EXPECT_TRUE(other.pixels() == Image(64, 48).pixels());
  }
  set_worker_threads(1);
}

// A batch (composite_all: one pass of bands of rows, every layer inside each band) against
// the same layers composited one after the other, whole or within regions, lazily cleared or
// over a cleared frame, on 1 and 2 threads: the same bytes and counts. The frame is large
// enough for several bands; layers overlap, so the order within a band matters (a control:
// the batch reversed differs).
TEST(Composite, ABatchEqualsItsLayersCompositedInTurn) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> offset(-80, 400);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int reversed_differs = 0;
  for (const int threads : {1, 2}) {
    set_worker_threads(threads);
    for (int k = 0; k < 12; ++k) {
      std::vector<Layer> layers;
      std::vector<ConvexPolygon> regions;
      std::vector<CompositeItem> items;
      const int count = 2 + k % 6;
      layers.reserve(static_cast<std::size_t>(count));
      regions.reserve(static_cast<std::size_t>(count));
      for (int n = 0; n < count; ++n) {
        const int w = 40 + static_cast<int>(unit(rng) * 500.0);
        const int h = 40 + static_cast<int>(unit(rng) * 350.0);
        layers.push_back(
            make_layer(testing::random_image(rng, w, h), testing::random_polygon(rng, w, h)));
        regions.push_back(testing::random_polygon(rng, 640, 400));
        items.push_back({&layers.back(), offset(rng), offset(rng) - 40,
                         unit(rng) < 0.5 ? nullptr : &regions.back()});
      }
      for (const bool lazy : {false, true}) {
        Image one_by_one(640, 400),
            batch = lazy ? testing::random_image(rng, 640, 400) : Image(640, 400);
        LazyClear clear;
        clear.start(batch.height());
        std::int64_t expected = 0;
        for (const CompositeItem& item : items) {
          expected += item.region == nullptr
                          ? composite_over(one_by_one, *item.layer, item.offset_x, item.offset_y)
                          : composite_over_region(one_by_one, *item.layer, item.offset_x,
                                                  item.offset_y, *item.region);
        }
        EXPECT_EQ(composite_all(batch, items, lazy ? &clear : nullptr), expected) << k;
        if (lazy) clear.finish(batch);
        ASSERT_TRUE(batch.pixels() == one_by_one.pixels())
            << "case " << k << ", threads " << threads << ", lazy " << lazy;
      }
      Image reversed(640, 400);
      composite_all(reversed, std::vector<CompositeItem>(items.rbegin(), items.rend()));
      Image forward(640, 400);
      composite_all(forward, items);
      reversed_differs += reversed.pixels() != forward.pixels();
    }
  }
  set_worker_threads(1);
  EXPECT_GT(reversed_differs, 12);
}

// Rows of runs (1 to 20 pixels) of opaque, transparent black and translucent layer pixels,
// so that the blend meets runs of eight opaque or clear pixels, broken runs and every
// remainder: each frame pixel is the layer pixel where it is opaque, the frame's where the
// layer pixel is transparent black, and the per-pixel formula elsewhere.
TEST(Composite, RunsOfOpaqueAndClearPixelsGiveThePerPixelRule) {
  std::mt19937 rng(21);
  std::uniform_int_distribution<int> run_length(1, 20), kind(0, 2), byte(0, 255);
  for (int k = 0; k < 40; ++k) {
    const int w = 1 + (k * 13) % 97, h = 1 + k % 5;
    Image source(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w;) {
        const int n = run_length(rng), what = kind(rng);
        for (int i = 0; i < n && x < w; ++i, ++x) {
          const auto a = static_cast<std::uint8_t>(what == 0 ? 255 : what == 1 ? 0 : byte(rng));
          const auto c = [&] {
            return static_cast<std::uint8_t>(what == 1 ? 0 : byte(rng) % (a + 1));
          };
          source.at(x, y) = Pixel{c(), c(), c(), a};
        }
      }
    }
    const Image before = testing::random_image(rng, w, h);
    for (const bool lazy : {false, true}) {
      Image frame = before;
      LazyClear clear;
      if (lazy) clear.start(h);
      const Layer layer = make_layer(source);
      const std::vector<CompositeItem> items{{&layer, 0, 0, nullptr}};
      ASSERT_EQ(composite_all(frame, items, lazy ? &clear : nullptr), std::int64_t{w} * h);
      if (lazy) clear.finish(frame);
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          const Pixel s = source.at(x, y);
          // Over cleared pixels (lazy) the frame held transparent black.
          const Pixel d = lazy ? Pixel{} : before.at(x, y);
          const bool clear_pixel = s.r == 0 && s.g == 0 && s.b == 0 && s.a == 0;
          const Pixel want = s.a == 255 ? s
                             : clear_pixel
                                 ? d
                                 : Pixel{static_cast<std::uint8_t>(expected_over(s.r, d.r, s.a)),
                                         static_cast<std::uint8_t>(expected_over(s.g, d.g, s.a)),
                                         static_cast<std::uint8_t>(expected_over(s.b, d.b, s.a)),
                                         static_cast<std::uint8_t>(expected_over(s.a, d.a, s.a))};
          ASSERT_EQ(frame.at(x, y), want)
              << "layer " << k << " lazy " << lazy << " at " << x << ", " << y;
        }
      }
    }
  }
}

TEST(Composite, EmptyLayersAndFramesAndFarOffsetsChangeNothing) {
  const Layer layer = make_layer(Image(4, 4, Pixel{9, 9, 9, 9}));
  Image frame(5, 5, Pixel{1, 1, 1, 1});
  EXPECT_EQ(composite_over(frame, layer, 2147483000, -2147483000), 0);
  EXPECT_EQ(composite_over(frame, make_layer(Image()), 0, 0), 0);
  Image empty;
  EXPECT_EQ(composite_over(empty, layer, 0, 0), 0);
  for (const Pixel& p : frame.pixels()) EXPECT_EQ(p, (Pixel{1, 1, 1, 1}));
  EXPECT_EQ(composite_over(frame, layer, 3, 3), 4);
}

}  // namespace
}  // namespace oflab
