// VTK rendering of a scene, the conventional baseline (see analysis/runs/vtk_scene_renderer.h).
#include "runs/vtk_scene_renderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "engine/wall_clock.h"
#include "report/charts.h"
#include "runs/vtk_content_actors.h"

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

// The texture-content polygons of one texture.
std::vector<const ScenePolygon*> polygons_of_texture(const Scene& scene, int texture) {
  std::vector<const ScenePolygon*> out;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.texture == texture && p.content == ContentKind::kTexture) out.push_back(&p);
  }
  return out;
}

// One unlit, textured actor per texture with the texture-content polygons it carries; true
// when a drawn texture has translucent texels.
bool add_texture_actors(const Scene& scene, vtkRenderer* renderer) {
  bool translucent = false;
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const std::vector<const ScenePolygon*> polygons =
        polygons_of_texture(scene, static_cast<int>(t));
    if (polygons.empty()) continue;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(outline_polydata(polygons));
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
    // One-sided polygons cull their backs; a two-sided sheet (ScenePolygon::two_sided) shows
    // both, so an actor carrying one draws both sides of all its polygons.
    const bool two_sided = std::any_of(polygons.begin(), polygons.end(),
                                       [](const ScenePolygon* p) { return p->two_sided; });
    actor->GetProperty()->SetBackfaceCulling(!two_sided);
    renderer->AddActor(actor);
    translucent = translucent || has_translucency(scene.textures[t]);
  }
  return translucent;
}

// Samples per pixel of the frame: the shaded contents' samples per pixel (0: none).
int multisamples(const Scene& scene, const LayerContent& content) {
  bool shaded = false;
  for (const ScenePolygon& p : scene.polygons) shaded = shaded || p.content == ContentKind::kShaded;
  const int samples = scene_content_quality(scene, content.quality);
  return shaded && samples > 1 ? samples : 0;
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
  vtkNew<vtkLight> light;
  Vec3 towards_light{0.0, 0.0, -1.0};  // viewer frame, unit
  Camera camera;
  double near = 0.05;
  Vec3 scene_centre{0.0};
  double scene_radius = 1.0;
};

VtkSceneRenderer::VtkSceneRenderer(const Scene& scene, const Camera& camera, double near,
                                   const LayerContent& content, bool multisample)
    : impl_(std::make_unique<Impl>()) {
  if (!display_available()) {
    throw std::runtime_error(
        "the VTK renderer needs an X display: run under xvfb-run -a on a headless machine");
  }
  Impl& m = *impl_;
  m.camera = camera;
  m.near = near;
  const bool translucent = add_texture_actors(scene, m.renderer);
  add_lit_contents(scene, content);
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
  m.window->SetMultiSamples(multisample ? multisamples(scene, content) : 0);
  m.window->SetAlphaBitPlanes(1);
  m.window->SetSize(camera.width, camera.height);
  m.window->AddRenderer(m.renderer);
  vtkCamera* vtk_camera = m.renderer->GetActiveCamera();
  vtk_camera->SetViewAngle(2.0 * std::atan(0.5 * camera.height / camera.focal_px) * 180.0 / kPi);
  image_ = Image(camera.width, camera.height);
}

VtkSceneRenderer::~VtkSceneRenderer() = default;

void VtkSceneRenderer::add_lit_contents(const Scene& scene, const LayerContent& content) {
  Impl& m = *impl_;
  m.renderer->AutomaticLightCreationOff();
  if (!scene_has_lit_content(scene)) return;
  const std::string problem = content_problem(content);
  if (!problem.empty()) throw std::invalid_argument("VtkSceneRenderer: content " + problem);
  LayerContent lit = content;
  lit.quality = scene_content_quality(scene, lit.quality);
  add_content_actors(scene, lit, m.renderer);
  m.towards_light = glm::normalize(content.light);
  m.light->SetLightTypeToSceneLight();
  m.light->PositionalOff();
  m.light->SetIntensity(1.0);
  m.light->SetColor(1.0, 1.0, 1.0);
  m.renderer->AddLight(m.light);
}

double VtkSceneRenderer::render(const ViewerPose& view) {
  Impl& m = *impl_;
  const auto t0 = WallClock::now();
  const Mat3 to_world = glm::transpose(view.rotation);
  const Vec3 eye = eye_position(view);
  const Vec3 forward = to_world * Vec3(0.0, 0.0, 1.0);
  const Vec3 up = to_world * Vec3(0.0, -1.0, 0.0);
  vtkCamera* camera = m.renderer->GetActiveCamera();
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(eye.x + forward.x, eye.y + forward.y, eye.z + forward.z);
  camera->SetViewUp(up.x, up.y, up.z);
  // The light is fixed to the viewer (core/content/layer_content.h): it shines from
  // towards_light, turned into the world with the viewer.
  const Vec3 from = eye + to_world * m.towards_light;
  m.light->SetPosition(from.x, from.y, from.z);
  m.light->SetFocalPoint(eye.x, eye.y, eye.z);
  const double far = glm::length(eye - m.scene_centre) + m.scene_radius;
  camera->SetClippingRange(m.near, std::max(far, 2.0 * m.near));
  m.window->Render();
  const int w = m.camera.width, h = m.camera.height;
  m.window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, m.pixels);
  const double ms = ms_since(t0);
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
