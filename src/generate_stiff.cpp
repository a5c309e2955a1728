// SPDX-License-Identifier: BSL-1.0
// `influence2d generate-stiff`: writes the stiff and extreme scenes of the
// precision study (verification/stiff_cases.hpp) as WKT and CSV files.

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "verification/stiff_cases.hpp"

namespace influence2d::cli {

namespace {

struct generate_stiff_options {
    std::string out;
    std::uint64_t seed = verification::default_stiff_seed;
    std::size_t count = verification::default_stiff_count;
};

void run_generate_stiff(const generate_stiff_options& o) {
    const std::filesystem::path dir = output_directory(o.out);
    const auto scenes = verification::stiff_data_scenes(o.seed, o.count);
    const auto files = verification::stiff_data_files(scenes);
    std::size_t bytes = 0;
    for (const auto& f : files) {
        write_atomically(dir / f.name, f.text);
        bytes += f.text.size();
    }
    std::cout << "generate-stiff: wrote " << files.size() << " files (" << scenes.size() << " scenes of "
              << verification::all_stiff_families().size() << " families, " << bytes << " bytes, seed " << o.seed
              << ") to " << o.out << "\n";
}

}  // namespace

void register_generate_stiff(CLI::App& app) {
    auto o = std::make_shared<generate_stiff_options>();
    CLI::App* sub = app.add_subcommand(
        "generate-stiff",
        "Write stiff and extreme test scenes for precision studies: for each family (near_collinear, sliver, "
        "needle, tiny_beside_huge, offset, scaled, subnormal, grazing, touching, centroid_on_edge_line, large, "
        "comb, spiral) COUNT scenes (one for large), each as <name>_a.wkt (static polygon), <name>_b.wkt "
        "(moving polygon in its own frame) and <name>_poses.csv (tx,ty,theta), many of them within a few ulps "
        "of contact; and manifest.csv (name,family,magnitude,a,b,poses). The output depends only on the seed "
        "and the count; the committed data/stiff uses the defaults.");
    sub->add_option("--out", o->out,
                    "Output directory, created if missing; files are written through "
                    "temporary files renamed into place")
        ->required()
        ->type_name("DIR");
    sub->add_option("--seed", o->seed, "Seed of the random shapes and poses")->capture_default_str()->type_name("S");
    sub->add_option("--count", o->count,
                    "Scenes per family (the large family always has one scene: its polygon has over 100,000 "
                    "vertices); the offset and scaled scenes spread over their magnitudes")
        ->capture_default_str()
        ->type_name("N")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1000}));
    sub->callback([o] { run_generate_stiff(*o); });
}

}  // namespace influence2d::cli
