#include "formats/obj_scene.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "formats/scene_file.h"

namespace oflab {

Scene read_obj_scene(const std::string& path, const Image& texture,
                     const std::string& texture_name) {
  // vtkOBJReader reports a missing file only through VTK's error output; check first.
  if (!std::ifstream(path)) throw SceneError(path + ": cannot open the file");
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  vtkCellArray* polys = data ? data->GetPolys() : nullptr;
  if (!polys || polys->GetNumberOfCells() == 0) {
    throw SceneError(path + ": no polygonal faces (is it a Wavefront OBJ file with 'f' lines?)");
  }
  Scene scene;
  scene.name = std::filesystem::path(path).stem().string();
  scene.description = "imported from " + path;
  scene.textures.push_back(texture);
  scene.texture_names.push_back(texture_name);
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  for (vtkIdType face = 0; polys->GetNextCell(ids); ++face) {
    std::vector<Vec3> vertices;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double p[3];
      data->GetPoints()->GetPoint(ids->GetId(k), p);
      vertices.emplace_back(p[0], p[1], p[2]);
    }
    const std::string name = "face " + std::to_string(face);
    try {
      scene.polygons.push_back(polygon_from_vertices(name, vertices, Vec3(0.0), 0));
    } catch (const std::invalid_argument& e) {
      throw SceneError(path + ": " + name + ": " + e.what());
    }
  }
  return scene;
}

}  // namespace oflab
