// SPDX-License-Identifier: BSL-1.0
#include "tool.hpp"

#include <exception>
#include <iostream>
#include <string>

#include "commands.hpp"

namespace influence2d::cli {

namespace {

/// Prints every line of `message` with the program's error prefix.
void print_error(const std::string& program, const std::string& message) {
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = message.find('\n', start);
        std::cerr << program << ": error: " << message.substr(start, end - start) << '\n';
        if (end == std::string::npos) break;
        start = end + 1;
    }
}

}  // namespace

int run_tool(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const exit_status& e) {
        return e.code;
    } catch (const CLI::ParseError& e) {
        // --help and --version are "errors" with exit code 0.
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const std::exception& e) {
        print_error(app.get_name(), e.what());
        return 2;
    }
    return 0;
}

}  // namespace influence2d::cli
