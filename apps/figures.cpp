// deepguide figures -o DIR [--only 4,6,...] [--format png|svg] [--width PX] [--data ROOT] [--json]
// The seed paper's Figs. 4, 6, 7, 8, 10, 11 and 12 from the bundled data
// (render/seed_figures.hpp says what each shows and from which file).
//
// The bundled data is looked for in --data, else $DEEPGUIDE_DATA, the
// current folder, the project the binary was built in (build/apps/deepguide
// -> the project's root), and the installed share/deepguide: the first that
// holds every figure's inputs.

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/render/seed_figures.hpp"

namespace deepguide::app {
namespace {

std::vector<std::string> data_candidates(const std::string& given) {
  if (!given.empty()) return {given};
  std::vector<std::string> out;
  if (const char* env = std::getenv("DEEPGUIDE_DATA")) out.emplace_back(env);
  out.emplace_back(".");
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    out.push_back((exe.parent_path() / ".." / "..").lexically_normal().string());
    out.push_back((exe.parent_path() / ".." / "share" / "deepguide").lexically_normal().string());
  }
  out.emplace_back(DEEPGUIDE_SOURCE_DIR);
  out.emplace_back(DEEPGUIDE_INSTALL_DATA);
  return out;
}

}  // namespace

void register_figures(CLI::App& app) {
  struct Options {
    std::string output, data, format = "png";
    std::vector<int> only;
    int width = 1200;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "figures", "Reproduce the seed paper's Figs. 4, 6, 7, 8, 10, 11 and 12 from the bundled scenarios and mission");
  cmd->add_option("-o,--output", o->output, "Folder to write the figures into (made when missing)")->required();
  cmd->add_option("--only", o->only, "Figure numbers to draw, comma-separated (default: all)")->delimiter(',');
  cmd->add_option("--format", o->format, "png or svg")->capture_default_str();
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--data", o->data, "Folder holding the bundled data/ (default: found beside the binary or here)");
  cmd->add_flag("--json", o->json, "Print what was drawn as JSON (files, summaries, the numbers behind them)");
  cmd->callback([o] {
    SeedFigureOptions options;
    options.data_root = locate_seed_data(data_candidates(o->data));
    options.output_dir = o->output;
    options.extension = o->format;
    options.width_px = o->width;
    options.only = o->only;
    const std::vector<WrittenSeedFigure> written = write_seed_figures(options, [&](const WrittenSeedFigure& w) {
      if (!o->json) std::cout << to_text(w) << std::flush;
    });
    if (o->json) {
      // Paths need not be UTF-8; JSON must be.
      std::cout
          << seed_figures_json(options.data_root, written).dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
          << "\n";
    }
  });
}

}  // namespace deepguide::app
