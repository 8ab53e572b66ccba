#include <exception>
#include <iostream>

#include "roadscale/util/error.h"

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "roadscale: metric monocular visual odometry. Recovers the absolute scale of a single "
      "car camera's motion every frame from the road plane and the known camera height."};
  app.set_version_flag("--version", ROADSCALE_VERSION);
  app.require_subcommand(1);
  roadscale::cli::RegisterDemoCommand(app);
  roadscale::cli::RegisterEvalCommand(app);
  roadscale::cli::RegisterRunCommand(app);
  roadscale::cli::RegisterRescaleCommand(app);
  roadscale::cli::RegisterSegmentCommand(app);
  roadscale::cli::RegisterSynthCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const roadscale::Error& e) {
    std::cerr << "roadscale: error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "roadscale: internal error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
