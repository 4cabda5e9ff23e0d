// VTK rendering of a scene, the conventional baseline (see analysis/runs/vtk_scene_renderer.h).
#include "runs/vtk_scene_renderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "report/charts.h"

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A straight-alpha RGBA vtkImageData of a premultiplied core image, rows flipped so that
// VTK's row 0 (texture t = 0) is the image's bottom row.
vtkSmartPointer<vtkImageData> texture_image(const Image& image) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width(), image.height(), 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
  for (int y = 0; y < image.height(); ++y) {
    const Pixel* row = image.row(image.height() - 1 - y);
    for (int x = 0; x < image.width(); ++x) {
      const Pixel p = unpremultiply(row[x]);
      unsigned char* o = out + 4 * (static_cast<std::size_t>(y) * image.width() + x);
      o[0] = p.r;
      o[1] = p.g;
      o[2] = p.b;
      o[3] = p.a;
    }
  }
  return data;
}

bool has_translucency(const Image& image) {
  for (const Pixel& p : image.pixels()) {
    if (p.a != 255) return true;
  }
  return false;
}

// The polygons of one texture as polydata: world points, one cell per polygon, texture
// coordinates (s, t) = (u, 1 - v).
vtkSmartPointer<vtkPolyData> polygons_of_texture(const Scene& scene, int texture) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  for (const ScenePolygon& p : scene.polygons) {
    if (p.texture != texture) continue;
    const std::vector<Vec2> outline = polygon_outline(p);
    const std::vector<Vec3> vertices = polygon_vertices(p);
    // VTK's polygons are counter-clockwise seen from their front; the outline's order in
    // (u, v) with v down may be either way.
    double turn = 0.0;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec2& a = outline[k];
      const Vec2& b = outline[(k + 1) % outline.size()];
      turn += a.x * b.y - b.x * a.y;
    }
    // In (u, v-down) a positive shoelace sum is clockwise on the texture as seen from the
    // front, so the order is reversed for VTK.
    const bool reverse = turn > 0.0;
    cells->InsertNextCell(static_cast<vtkIdType>(vertices.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const std::size_t k = reverse ? vertices.size() - 1 - i : i;
      cells->InsertCellPoint(points->InsertNextPoint(vertices[k].x, vertices[k].y, vertices[k].z));
      tcoords->InsertNextTuple2(outline[k].x, 1.0 - outline[k].y);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  data->GetPointData()->SetTCoords(tcoords);
  return data;
}

}  // namespace

bool display_available() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

struct VtkSceneRenderer::Impl {
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkUnsignedCharArray> pixels;
  Camera camera;
  double near = 0.05;
  Vec3 scene_centre{0.0};
  double scene_radius = 1.0;
};

VtkSceneRenderer::VtkSceneRenderer(const Scene& scene, const Camera& camera, double near)
    : impl_(std::make_unique<Impl>()) {
  if (!display_available()) {
    throw std::runtime_error(
        "the VTK renderer needs an X display: run under xvfb-run -a on a headless machine");
  }
  Impl& m = *impl_;
  m.camera = camera;
  m.near = near;
  bool translucent = false;
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(polygons_of_texture(scene, static_cast<int>(t)));
    vtkNew<vtkTexture> texture;
    texture->SetInputData(texture_image(scene.textures[t]));
    texture->InterpolateOff();  // nearest texel, as the engine's point sampling
    texture->MipmapOff();
    texture->RepeatOff();
    texture->EdgeClampOn();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    actor->GetProperty()->LightingOff();  // the texture's colour, unshaded
    actor->GetProperty()->BackfaceCullingOn();
    m.renderer->AddActor(actor);
    translucent = translucent || has_translucency(scene.textures[t]);
  }
  // Bounding sphere of the scene for the far clipping plane.
  Vec3 lo(1e300), hi(-1e300);
  for (const ScenePolygon& p : scene.polygons) {
    for (const Vec3& v : polygon_vertices(p)) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  if (!scene.polygons.empty()) {
    m.scene_centre = 0.5 * (lo + hi);
    m.scene_radius = 0.5 * glm::length(hi - lo) + 1.0;
  }
  m.renderer->SetBackground(0.0, 0.0, 0.0);
  m.renderer->SetBackgroundAlpha(0.0);
  if (translucent) {
    // Cut-out textures need order-independent transparency to composite correctly.
    m.renderer->SetUseDepthPeeling(1);
    m.renderer->SetMaximumNumberOfPeels(8);
    m.renderer->SetOcclusionRatio(0.0);
  }
  // The process's shared X connection (analysis/report/charts.h): a window that opened its own
  // would abort the process if a busy X server refused the connection.
  m.window->SetDisplayId(shared_x_display());
  m.window->SetOffScreenRendering(1);
  m.window->SetMultiSamples(0);
  m.window->SetAlphaBitPlanes(1);
  m.window->SetSize(camera.width, camera.height);
  m.window->AddRenderer(m.renderer);
  vtkCamera* vtk_camera = m.renderer->GetActiveCamera();
  vtk_camera->SetViewAngle(2.0 * std::atan(0.5 * camera.height / camera.focal_px) * 180.0 / kPi);
  image_ = Image(camera.width, camera.height);
}

VtkSceneRenderer::~VtkSceneRenderer() = default;

double VtkSceneRenderer::render(const ViewerPose& view) {
  Impl& m = *impl_;
  const auto t0 = std::chrono::steady_clock::now();
  const Mat3 to_world = glm::transpose(view.rotation);
  const Vec3 eye = eye_position(view);
  const Vec3 forward = to_world * Vec3(0.0, 0.0, 1.0);
  const Vec3 up = to_world * Vec3(0.0, -1.0, 0.0);
  vtkCamera* camera = m.renderer->GetActiveCamera();
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(eye.x + forward.x, eye.y + forward.y, eye.z + forward.z);
  camera->SetViewUp(up.x, up.y, up.z);
  const double far = glm::length(eye - m.scene_centre) + m.scene_radius;
  camera->SetClippingRange(m.near, std::max(far, 2.0 * m.near));
  m.window->Render();
  const int w = m.camera.width, h = m.camera.height;
  m.window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, m.pixels);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  // OpenGL's rows run bottom to top; the framebuffer holds colour already multiplied by
  // alpha over the transparent black background, i.e. premultiplied.
  const unsigned char* in = m.pixels->GetPointer(0);
  for (int y = 0; y < h; ++y) {
    Pixel* row = image_.row(h - 1 - y);
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = in + 4 * (static_cast<std::size_t>(y) * w + x);
      row[x] = Pixel{std::min(p[0], p[3]), std::min(p[1], p[3]), std::min(p[2], p[3]), p[3]};
    }
  }
  return ms;
}

}  // namespace oflab
