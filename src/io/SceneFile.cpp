#include "io/SceneFile.hpp"

#include <algorithm>

#include "io/SceneSchema.hpp"
#include "io/SceneTables.hpp"

namespace og::io {

SceneSettings readSceneFile(const std::filesystem::path& file, SceneSettings s) {
  detail::readSceneTables(file, detail::parseTomlOrJson(file), s, detail::SceneForm::File);
  validateScene(s, file.string());
  return s;
}

void writeSceneFile(const std::filesystem::path& file, const SceneSettings& scene) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  detail::writeTextFile(file, ext == ".json" ? detail::sceneJson(scene, true).dump(2) + "\n"
                                             : sceneToml(scene, "", true));
}

}  // namespace og::io
