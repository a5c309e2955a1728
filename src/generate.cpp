// SPDX-License-Identifier: BSL-1.0
// `influence2d generate`: writes the paper's polygon families as WKT files.

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "verification/families.hpp"

namespace influence2d::cli {

namespace {

struct generate_options {
    std::string out;
    std::uint64_t seed = verification::default_family_seed;
    std::vector<std::size_t> sizes = verification::default_family_sizes();
};

void run_generate(const generate_options& o) {
    const std::filesystem::path dir = output_directory(o.out);
    std::size_t files = 0, vertices = 0;
    for (const auto f : verification::all_families) {
        for (const std::size_t n : o.sizes) {
            write_atomically(dir / verification::family_file_name(f, n), verification::family_file_text(f, n, o.seed));
            ++files;
            vertices += n;
        }
    }
    std::cout << "generate: wrote " << files << " files (" << std::size(verification::all_families) << " families x "
              << o.sizes.size() << " sizes, " << vertices << " vertices, seed " << o.seed << ") to " << o.out << "\n";
}

}  // namespace

void register_generate(CLI::App& app) {
    auto o = std::make_shared<generate_options>();
    CLI::App* sub =
        app.add_subcommand("generate",
                           "Write the paper's polygon families (convex, starred, irregular, contour, hole) as WKT, "
                           "one file <family>_<n>.wkt per family and vertex count. Every polygon has its vertices "
                           "within radius 50 of the origin and vertex 0 at (50, 0); the output is the same on every "
                           "platform for a given seed.");
    sub->add_option("--out", o->out,
                    "Output directory, created if missing (required: the committed families are data/families "
                    "of the source tree); files are written through temporary files renamed into place")
        ->required()
        ->type_name("DIR");
    sub->add_option("--seed", o->seed, "Seed of the random shapes; the committed data/families use the default")
        ->capture_default_str()
        ->type_name("S");
    sub->add_option("--sizes", o->sizes,
                    "Vertex counts (each >= 8), separated by commas or spaces "
                    "[default: 8,16,32,64,128,256,512,1024]")
        ->delimiter(',')
        ->type_name("N,...")
        ->check(CLI::Range(std::size_t{8}, std::size_t{1} << 24));
    sub->callback([o] { run_generate(*o); });
}

}  // namespace influence2d::cli
