// SPDX-License-Identifier: BSL-1.0
#pragma once
// A small SVG writer for `influence2d render`: XML escaping, compact numbers,
// elements built attribute by attribute, and path data.

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace influence2d::cli::svg {

/// `text` made safe as XML character data or attribute value: the markup
/// characters become entities; bytes that are not well-formed UTF-8 and
/// characters XML 1.0 does not allow (controls other than tab, line feed and
/// carriage return; U+FFFE, U+FFFF) become '?'.
inline std::string escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80) {
            switch (byte) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            case '\t':
            case '\n':
            case '\r': out += static_cast<char>(byte); break;
            default: out += byte < 0x20 || byte == 0x7f ? '?' : static_cast<char>(byte);
            }
            ++i;
            continue;
        }
        // A multi-byte sequence: its length from the lead byte, then the
        // continuation bytes, the shortest form and the range checked.
        const std::size_t length = byte >= 0xc2 && byte <= 0xdf   ? 2
                                   : byte >= 0xe0 && byte <= 0xef ? 3
                                   : byte >= 0xf0 && byte <= 0xf4 ? 4
                                                                  : 0;
        unsigned long code = length == 4 ? byte & 0x07u : length == 3 ? byte & 0x0fu : byte & 0x1fu;
        bool valid = length != 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            valid = (next & 0xc0u) == 0x80u;
            code = (code << 6) | (next & 0x3fu);
        }
        valid = valid && !(length == 3 && code < 0x800) && !(length == 4 && (code < 0x10000 || code > 0x10ffff)) &&
                !(code >= 0xd800 && code <= 0xdfff) && code != 0xfffe && code != 0xffff;
        if (valid) {
            out.append(text.substr(i, length));
            i += length;
        } else {
            out += '?';
            ++i;
        }
    }
    return out;
}

/// x with at most `digits` digits after the point, trailing zeros dropped
/// ("-0" written as "0").
inline std::string number(double x, int digits = 3) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
    std::string s = buffer;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

/// One element, built attribute by attribute:
/// element("rect").num("x", 1.5).attr("class", "a").empty() gives
/// <rect x="1.5" class="a"/>. Values are escaped.
class element {
public:
    explicit element(std::string_view name) : name_(name), text_("<" + name_) {}

    element& attr(std::string_view name, std::string_view value) {
        text_ += ' ';
        text_ += name;
        text_ += "=\"" + escape(value) + "\"";
        return *this;
    }
    element& num(std::string_view name, double value, int digits = 3) { return attr(name, number(value, digits)); }
    element& index(std::string_view name, std::size_t value) { return attr(name, std::to_string(value)); }

    /// The element without content.
    std::string empty() const { return text_ + "/>\n"; }
    /// The start tag alone (the caller writes the content and close(name)).
    std::string open() const { return text_ + ">\n"; }
    /// The element with `content` (escaped) as its text.
    std::string with_text(std::string_view content) const {
        return text_ + ">" + escape(content) + "</" + name_ + ">\n";
    }

private:
    std::string name_;
    std::string text_;
};

/// The end tag of an element opened with element::open().
inline std::string close(std::string_view name) { return "</" + std::string(name) + ">\n"; }

/// Path data (the `d` attribute) in the coordinates of the enclosing group.
class path_data {
public:
    path_data& move(double x, double y) { return command('M', x, y); }
    path_data& line(double x, double y) { return command('L', x, y); }
    /// A circular arc of radius r to (x, y); `positive`: turning from the
    /// x axis towards the y axis of the user space (the sweep flag).
    path_data& arc(double r, bool positive, double x, double y) {
        text_ += "A" + number(r) + " " + number(r) + " 0 0 " + (positive ? "1 " : "0 ");
        return point(x, y);
    }
    path_data& close() {
        text_ += 'Z';
        return *this;
    }
    const std::string& str() const { return text_; }
    bool empty() const { return text_.empty(); }

private:
    path_data& command(char c, double x, double y) {
        text_ += c;
        return point(x, y);
    }
    path_data& point(double x, double y) {
        text_ += number(x) + " " + number(y) + " ";
        return *this;
    }
    std::string text_;
};

}  // namespace influence2d::cli::svg
