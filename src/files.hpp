// SPDX-License-Identifier: BSL-1.0
#pragma once
// Writing output files so that a reader never sees a half-written one.

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace influence2d::cli {

/// Writes `text` to `path` through a temporary file in the same directory,
/// renamed into place, so that a reader never sees a half-written file.
inline void write_atomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::path temp = path;
    temp += ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(temp.string() + ": cannot open for writing");
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            throw std::runtime_error(temp.string() + ": write error");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error(path.string() + ": cannot rename the temporary file into place");
    }
}

}  // namespace influence2d::cli
