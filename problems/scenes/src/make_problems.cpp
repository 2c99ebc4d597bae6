// adsd_make_problems OUTPUT_DIR: writes the meshes of every shipped problem (NAME_env.obj and, for
// generated robots, NAME_robot.obj) into OUTPUT_DIR, beside the .cfg files that refer to them.
// The build runs it (target adsd_problems); see problems/README.md.
#include <filesystem>
#include <iostream>

#include "adsd/error.h"
#include "adsd/problem_scenes.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: adsd_make_problems OUTPUT_DIR\n";
    return 2;
  }
  const std::filesystem::path dir(argv[1]);
  try {
    std::filesystem::create_directories(dir);
    for (const adsd::shapes::ProblemScene& scene : adsd::shapes::allProblemScenes()) {
      adsd::shapes::writeObj(scene.environment, (dir / (scene.name + "_env.obj")).string());
      if (!scene.robot.empty()) adsd::shapes::writeObj(scene.robot.front(), (dir / (scene.name + "_robot.obj")).string());
    }
  } catch (const adsd::InputError& e) {
    std::cerr << "adsd_make_problems: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "adsd_make_problems: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
