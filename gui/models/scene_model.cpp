#include "models/scene_model.h"

#include "adapters/frame_images.h"
#include "adapters/texture.h"

namespace oflab {

SceneModel::SceneModel(PlanePanel* panel, QImage texture, QObject* parent)
    : QObject(parent), panel_(panel), texture_(std::move(texture)) {}

SceneModel::SceneModel(QObject* parent)
    : QObject(parent),
      own_panel_(std::make_unique<PlanePanel>(image_from_qimage(default_texture()))),
      panel_(own_panel_.get()),
      texture_(default_texture()) {}

SceneModel::~SceneModel() = default;

void SceneModel::set_loop_override(int frames) {
  panel_->set_loop_override(frames);
  emit scene_changed();
}

bool SceneModel::set_scene(const PlaneScene& scene) {
  const std::string problem = panel_->set_scene(scene);
  if (!problem.empty()) {
    emit scene_rejected(QString::fromStdString(problem));
    return false;
  }
  emit source_changed();
  emit scene_changed();
  return true;
}

bool SceneModel::set_script(const MotionScript& script, const QString& name) {
  const std::string problem = panel_->set_script(script, name.toStdString());
  if (!problem.empty()) {
    emit scene_rejected(QString::fromStdString(problem));
    return false;
  }
  emit source_changed();
  emit scene_changed();
  return true;
}

bool SceneModel::set_texture(const QImage& texture, const QString& source_name) {
  if (texture.isNull() || texture.width() < 1 || texture.height() < 1) {
    emit scene_rejected(
        QStringLiteral("cannot use %1 as a texture: not a readable image").arg(source_name));
    return false;
  }
  panel_->set_texture(image_from_qimage(texture), source_name.toStdString());
  texture_ = texture;
  emit texture_changed();
  emit source_changed();
  emit scene_changed();
  return true;
}

void SceneModel::set_frame(int frame) {
  const int next = panel_->landing_frame(frame);
  if (next == panel_->frame()) return;
  panel_->set_frame(next);
  emit scene_changed();
}

void SceneModel::panel_replaced(const QImage& texture) {
  texture_ = texture;
  emit texture_changed();
  emit source_changed();
  emit scene_changed();
}

}  // namespace oflab
