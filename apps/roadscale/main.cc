#include <cctype>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <malloc.h>

#include "roadscale/util/error.h"

#include "commands.h"

namespace {

// The subcommands as registered (CLI11's overloads need the filter's type spelled out).
std::vector<const CLI::App*> Subcommands(const CLI::App& app) {
  return app.get_subcommands(std::function<bool(const CLI::App*)>());
}

bool IsSubcommand(const CLI::App& app, const std::string& word) {
  for (const CLI::App* command : Subcommands(app)) {
    if (command->check_name(word)) return true;
  }
  return false;
}

// "demo, eval, ..." for the message about an unknown subcommand.
std::string SubcommandNames(const CLI::App& app) {
  std::string names;
  for (const CLI::App* command : Subcommands(app)) {
    names += (names.empty() ? "" : ", ") + command->get_name();
  }
  return names;
}

// "PATH: too many levels of symbolic links", in the style of the other messages.
std::string FileSystemErrorText(const std::filesystem::filesystem_error& error) {
  std::string reason = error.code().message();
  if (!reason.empty()) {
    reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
  }
  if (error.path1().empty()) return reason;
  return error.path1().string() + ": " + reason;
}

// Every frame allocates and frees the same few megabytes (images, pyramids, masks, the
// network's tensors). glibc serves blocks above 128 KB with mmap and gives freed heap back to
// the kernel, so each frame paid for those pages again: 11 % of a run's CPU went to page
// faults (docs/benchmark-history.md, "Freed memory kept for the next frame"). Blocks up to 64 MB
// now come from the heap, and freed heap is kept for reuse up to 512 MB.
void KeepFreedMemoryForReuse() {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

}  // namespace

int main(int argc, char** argv) {
  KeepFreedMemoryForReuse();
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
  roadscale::cli::RegisterBatchCommand(app);

  // CLI11 would take an unknown word for a stray argument and say "A subcommand is required".
  if (argc > 1 && argv[1][0] != '-' && !IsSubcommand(app, argv[1])) {
    std::cerr << "roadscale: error: unknown subcommand '" << argv[1] << "' (expected one of "
              << SubcommandNames(app) << ")\n";
    return 1;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    // One line and status 1, as for every other error (CLI11's own exit codes are 100+).
    // CLI11 checks the required options before it reports the words it did not recognise,
    // so a mistyped option would read as a missing one: the unrecognised words come first.
    const std::vector<std::string> unrecognised = app.remaining(/*recurse=*/true);
    const std::string message =
        dynamic_cast<const CLI::RequiredError*>(&e) != nullptr && !unrecognised.empty()
            ? CLI::ExtrasError(unrecognised).what()
            : e.what();
    std::cerr << "roadscale: error: " << message << " (see roadscale --help)\n";
    return 1;
  } catch (const roadscale::Error& e) {
    std::cerr << "roadscale: error: " << e.what() << '\n';
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the file system refuses (a symlink loop, a folder without permission) surfaces
    // from any std::filesystem call on it: one line naming it, as every other input error.
    std::cerr << "roadscale: error: " << FileSystemErrorText(e) << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "roadscale: internal error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
