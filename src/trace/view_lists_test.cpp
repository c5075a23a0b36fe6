#include "trace/view_lists.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/rng.h"
#include "trace/world.h"

namespace prt {
namespace {

// Spheres and boxes in front of the camera, one around the eye, a floor; much open sky.
Scene viewScene(int count) {
  Scene scene;
  scene.camera.eye = Vec3(0, 2, -8);
  scene.camera.lookAt = Vec3(0, 1, 0);
  scene.image.width = 96;
  scene.image.height = 72;
  Rng rng(6);
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * 8 - 4, rng.uniform() * 2, rng.uniform() * 8 - 2);
    if (i % 2 == 0) {
      scene.objects.push_back({SphereShape{c, 0.2 + 0.4 * rng.uniform()}, Material{}});
    } else {
      scene.objects.push_back({BoxShape{c, c + Vec3(0.3 + rng.uniform())}, Material{}});
    }
  }
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, Material{}});
  return scene;
}

TEST(ViewListsTest, CameraRaysMeetTheSameAsThroughTheBvh) {
  const Scene scene = viewScene(30);
  const World world(scene);
  const int w = scene.image.width, h = scene.image.height;
  const PinholeCamera camera(scene.camera, w, h);
  const ViewLists view(camera, w, h, world.itemBounds());
  Rng rng(7);
  int listed = 0, empty = 0, hits = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto candidates = view.candidates(x, y);
      if (!candidates) continue;
      ++listed;
      empty += candidates->empty();
      EXPECT_LE(candidates->size(), 8u);
      // Samples anywhere in the pixel, its corners included.
      for (int s = 0; s < 6; ++s) {
        const double dx = s == 0 ? 0 : s == 1 ? std::nextafter(1.0, 0.0) : rng.uniform();
        const double dy = s == 0 ? 0 : s == 1 ? std::nextafter(1.0, 0.0) : rng.uniform();
        const Ray ray = camera.generateRay(x + dx, y + dy);
        const double inf = std::numeric_limits<double>::infinity();
        Hit a, b;
        const bool found = world.intersect(ray, 0, inf, a);
        ASSERT_EQ(world.intersectAmong(*candidates, ray, 0, inf, b), found) << x << "," << y;
        if (!found) continue;
        ++hits;
        EXPECT_EQ(a.object, b.object);
        EXPECT_EQ(a.t, b.t);
        EXPECT_EQ(a.normal, b.normal);
      }
    }
  }
  EXPECT_GT(listed, w * h / 2);
  EXPECT_GT(empty, w * h / 10);
  EXPECT_GT(hits, w * h);
}

TEST(ViewListsTest, CrowdedTilesAndPixelsOutsideGoToTheBvh) {
  // Forty boxes stacked straight ahead: every tile they cover would list all of them.
  std::vector<Bounds> items;
  for (int i = 0; i < 40; ++i) {
    Bounds b;
    b.lo = Vec3(-1, -1, 1.0 * i);
    b.hi = Vec3(1, 1, 1.0 * i + 0.5);
    items.push_back(b);
  }
  const PinholeCamera camera(Camera{}, 64, 48);  // at (0, 0, -5) looking towards +z
  const ViewLists view(camera, 64, 48, items);
  EXPECT_FALSE(view.candidates(32, 24));  // the middle: crowded
  ASSERT_TRUE(view.candidates(0, 0));     // a corner: open
  EXPECT_TRUE(view.candidates(0, 0)->empty());
  EXPECT_FALSE(view.candidates(-1, 0));
  EXPECT_FALSE(view.candidates(64, 0));
  EXPECT_FALSE(view.candidates(0, 48));
  // With a higher limit the middle is listed.
  const ViewLists generous(camera, 64, 48, items, 100);
  ASSERT_TRUE(generous.candidates(32, 24));
  EXPECT_EQ(generous.candidates(32, 24)->size(), 40u);
}

TEST(ViewListsTest, ABoxAroundTheEyeCoversTheWholeImage) {
  Bounds around;
  around.lo = Vec3(-10, -10, -10);
  around.hi = Vec3(10, 10, 10);
  const PinholeCamera camera(Camera{}, 32, 24);
  const ViewLists view(camera, 32, 24, {around});
  for (const auto& [x, y] : {std::pair{0, 0}, {31, 23}, {16, 12}}) {
    const auto candidates = view.candidates(x, y);
    ASSERT_TRUE(candidates);
    EXPECT_EQ(candidates->size(), 1u);
  }
}

TEST(ViewListsTest, NoItemsNoLists) {
  const PinholeCamera camera(Camera{}, 32, 24);
  EXPECT_FALSE(ViewLists(camera, 32, 24, {}).candidates(0, 0));
}

}  // namespace
}  // namespace prt
