// VTK actors of the lit contents (see analysis/runs/vtk_content_actors.h).
#include "runs/vtk_content_actors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace oflab {
namespace {

unsigned char unit_byte(double c) {
  return static_cast<unsigned char>(std::lround(255.0 * std::clamp(c, 0.0, 1.0)));
}

// The material's lighting on a VTK property (see the header for the specular power).
void set_material(vtkProperty* property, const ContentMaterial& m, bool textured) {
  const Vec3 colour = textured ? Vec3(1.0) : m.albedo;
  property->SetColor(colour.r, colour.g, colour.b);
  property->SetAmbient(kContentAmbient);
  property->SetDiffuse(kContentDiffuse);
  property->SetSpecular(m.specular);
  property->SetSpecularColor(1.0, 1.0, 1.0);
  property->SetSpecularPower(m.shininess / 4.0);
  property->LightingOn();
  property->BackfaceCullingOn();
}

// ---- Impostors ----

struct PartGeometry {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> normals;
  PartGeometry() { normals->SetNumberOfComponents(3); }
};

// Adds the faces of one impostor polygon, each counter-clockwise seen along its normal.
int add_facade(const ScenePolygon& polygon, int detail, std::map<FacadePart, PartGeometry>& parts) {
  const Vec3 right = polygon_right(polygon);
  const auto world = [&](const Vec3& c) {
    return polygon.centre + c.x * right + c.y * polygon.up + c.z * polygon.front;
  };
  int count = 0;
  for (const FacadeFace& face : facade_faces(polygon.size, detail)) {
    PartGeometry& g = parts[face.part];
    const Vec3 n =
        face.normal.x * right + face.normal.y * polygon.up + face.normal.z * polygon.front;
    std::array<Vec3, 4> c;
    for (int k = 0; k < 4; ++k) c[k] = world(face.corners[k]);
    const bool reverse = glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), n) < 0.0;
    g.cells->InsertNextCell(4);
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = c[reverse ? 3 - k : k];
      g.cells->InsertCellPoint(g.points->InsertNextPoint(p.x, p.y, p.z));
      g.normals->InsertNextTuple3(n.x, n.y, n.z);
    }
    ++count;
  }
  return count;
}

void add_part_actor(FacadePart part, PartGeometry& g, vtkRenderer* renderer) {
  vtkNew<vtkPolyData> data;
  data->SetPoints(g.points);
  data->SetPolys(g.cells);
  // Point normals, the face's own at its four points: as flat as cell normals, without a
  // per-fragment cell-normal lookup in the shader.
  data->GetPointData()->SetNormals(g.normals);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  set_material(actor->GetProperty(), facade_material(part), false);
  actor->GetProperty()->SetInterpolationToGouraud();
  renderer->AddActor(actor);
}

// ---- Shaded brick ----

struct BrickTextures {
  vtkSmartPointer<vtkTexture> albedo;
  vtkSmartPointer<vtkTexture> normal;
};

vtkSmartPointer<vtkTexture> filtered_texture(vtkImageData* image) {
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->SetMaximumAnisotropicFiltering(16.0f);
  texture->RepeatOff();
  texture->EdgeClampOn();
  return texture;
}

// The brick of a rectangle of `size` world units: texel (i, j) of a vtkImageData (row 0 at
// the bottom, t = 0) samples brick_at at its centre, x from the left, y down from the top.
// The normal map holds the tangent-space normal (R, U, F) = normalize(-slope.x, slope.y, 1)
// as colour n / 2 + 1/2 (VTK's tangent frame: T = R, B = N x T = U).
BrickTextures bake_brick(const Vec2& size) {
  const int w =
      std::clamp(static_cast<int>(std::ceil(size.x * kBrickTexelsPerUnit)), 1, kMaxBakedTexels);
  const int h =
      std::clamp(static_cast<int>(std::ceil(size.y * kBrickTexelsPerUnit)), 1, kMaxBakedTexels);
  vtkNew<vtkImageData> albedo, normal;
  for (vtkImageData* image : {albedo.Get(), normal.Get()}) {
    image->SetDimensions(w, h, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  }
  auto* a = static_cast<unsigned char*>(albedo->GetScalarPointer());
  auto* n = static_cast<unsigned char*>(normal->GetScalarPointer());
  for (int j = 0; j < h; ++j) {
    const double y = (1.0 - (j + 0.5) / h) * size.y;
    for (int i = 0; i < w; ++i) {
      const BrickSample b = brick_at((i + 0.5) / w * size.x, y);
      const Vec3 tn = glm::normalize(Vec3(-b.slope.x, b.slope.y, 1.0));
      const std::size_t o = 3 * (static_cast<std::size_t>(j) * w + i);
      for (int k = 0; k < 3; ++k) {
        a[o + k] = unit_byte(b.material.albedo[k]);
        n[o + k] = unit_byte(0.5 * tn[k] + 0.5);
      }
    }
  }
  return {filtered_texture(albedo), filtered_texture(normal)};
}

void add_shaded_actor(const ScenePolygon& polygon, const BrickTextures& textures,
                      vtkRenderer* renderer) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(outline_polydata({&polygon}));
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(textures.albedo);
  vtkProperty* property = actor->GetProperty();
  BrickSample brick = brick_at(0.1, 0.035);  // a brick's centre: its material
  set_material(property, brick.material, true);
  property->SetInterpolationToPhong();
  property->SetNormalTexture(textures.normal);
  renderer->AddActor(actor);
}

}  // namespace

vtkSmartPointer<vtkPolyData> outline_polydata(const std::vector<const ScenePolygon*>& polygons) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> tcoords, normals, tangents;
  tcoords->SetNumberOfComponents(2);
  normals->SetNumberOfComponents(3);
  tangents->SetNumberOfComponents(3);
  tangents->SetName("tangents");
  for (const ScenePolygon* p : polygons) {
    const std::vector<Vec2> outline = polygon_outline(*p);
    const std::vector<Vec3> vertices = polygon_vertices(*p);
    const Vec3 right = polygon_right(*p);
    // In (u, v-down) a positive shoelace sum is clockwise on the texture as seen from the
    // front, so the order is reversed for VTK.
    double turn = 0.0;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec2& a = outline[k];
      const Vec2& b = outline[(k + 1) % outline.size()];
      turn += a.x * b.y - b.x * a.y;
    }
    const bool reverse = turn > 0.0;
    cells->InsertNextCell(static_cast<vtkIdType>(vertices.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const std::size_t k = reverse ? vertices.size() - 1 - i : i;
      cells->InsertCellPoint(points->InsertNextPoint(vertices[k].x, vertices[k].y, vertices[k].z));
      tcoords->InsertNextTuple2(outline[k].x, 1.0 - outline[k].y);
      normals->InsertNextTuple3(p->front.x, p->front.y, p->front.z);
      tangents->InsertNextTuple3(right.x, right.y, right.z);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  data->GetPointData()->SetTCoords(tcoords);
  data->GetPointData()->SetNormals(normals);
  data->GetPointData()->SetTangents(tangents);
  return data;
}

bool scene_has_lit_content(const Scene& scene) {
  return std::any_of(scene.polygons.begin(), scene.polygons.end(),
                     [](const ScenePolygon& p) { return p.content != ContentKind::kTexture; });
}

int add_content_actors(const Scene& scene, const LayerContent& content, vtkRenderer* renderer) {
  std::map<FacadePart, PartGeometry> parts;
  std::map<std::pair<double, double>, BrickTextures> bricks;
  int faces = 0;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.content == ContentKind::kImpostor) {
      faces += add_facade(p, content.quality, parts);
    } else if (p.content == ContentKind::kShaded) {
      const auto key = std::make_pair(p.size.x, p.size.y);
      auto it = bricks.find(key);
      if (it == bricks.end()) it = bricks.emplace(key, bake_brick(p.size)).first;
      add_shaded_actor(p, it->second, renderer);
      ++faces;
    }
  }
  for (auto& [part, geometry] : parts) add_part_actor(part, geometry, renderer);
  return faces;
}

}  // namespace oflab
