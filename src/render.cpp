// SPDX-License-Identifier: BSL-1.0
// `influence2d render`: one SVG picture of a scene. The static polygon A with
// its covering triangles (coloured by sign), its centroid and its influence
// cones; at each chosen frame the moving polygon B, the extended areas of A's
// candidate edges (those whose area holds B's centroid) and the colliding edge
// pairs the exact detector reports.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/candidate_edges.hpp"
#include "influence2d/influence/extended_area_outline.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "report.hpp"
#include "scene_input.hpp"
#include "svg.hpp"

namespace influence2d::cli {

namespace {

struct render_options {
    scene_options scene;
    double distance = 0.0;
    std::string shape = "capsule";
    std::string frames;  // the list as given, commas included; empty: chosen by the command
    std::string out;
    std::size_t width = 800;
    bool no_cones = false;
    bool no_triangles = false;
    bool no_extended = false;
};

/// Where the poses come from, for the title and the messages.
std::string motion_of(const scene_options& o) {
    if (!o.poses_path.empty()) return shown_name(o.poses_path);
    return "the " + o.trajectory + " trajectory (gap " + general(o.gap) + ")";
}

/// The frames to draw: those asked for (each checked against the frame
/// count), or four spread evenly from frame 0 plus the first colliding frame,
/// found with the certified detector (exact answers). `first` gets the first
/// colliding frame when the whole sequence was run (frames not given).
std::vector<std::size_t> chosen_frames(const render_options& o, const scene_input& in, const detector_options& options,
                                       std::string& first) {
    const std::size_t count = in.poses.size();
    std::vector<std::size_t> frames;
    // Split here rather than by the option parser, so that an empty element
    // ("1,,2", a trailing comma) is refused, not dropped.
    std::vector<std::string> items;
    if (!o.frames.empty())
        for (std::size_t start = 0;;) {
            const std::size_t comma = o.frames.find(',', start);
            items.push_back(o.frames.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    for (const std::string& text : items) {
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
            throw invalid_input("--frames: '" + text + "' is not a frame number (frames are numbered from 0)");
        // A number too large for std::size_t is out of range all the same.
        std::size_t f = 0;
        const bool fits = std::from_chars(text.data(), text.data() + text.size(), f).ec == std::errc();
        if (!fits || f >= count)
            throw invalid_input("--frames: frame " + text + " is out of range: " + motion_of(o.scene) + " has " +
                                std::to_string(count) + " frame" + (count == 1 ? "" : "s") +
                                (count == 0 ? "" : " (0 to " + std::to_string(count - 1) + ")"));
        frames.push_back(f);
    }
    if (frames.empty()) {
        for (std::size_t k = 0; k < 4 && k < count; ++k) frames.push_back(k * count / 4);
        certified_detector<detector> scan(in.a, in.b, options);
        first = "none";
        for (std::size_t i = 0; i < count; ++i)
            if (scan.collide(in.poses[i]).collides) {
                frames.push_back(i);
                first = "frame " + std::to_string(i);
                break;
            }
    }
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

/// One drawn frame: the exact detector's answer, B posed (in double, for the
/// drawing) and A's candidate edges (stored numbering) for B's centroid.
struct shown_frame {
    std::size_t index = 0;
    frame_result result;
    std::vector<point<double>> b;
    point<double> p;
    std::vector<std::size_t> candidates;
};

/// The frames as the exact detector answers them, with witnesses; the
/// candidate edges are decided exactly too, for B's exactly posed centroid.
std::vector<shown_frame> evaluate(const scene_input& in, const std::vector<std::size_t>& frames,
                                  detector_options options, const triangle_covering<exact_rational>& cov, double n) {
    options.witness = true;
    detector<exact_rational> det(in.a, in.b, options);
    const exact_rational reach(n);
    std::vector<shown_frame> shown;
    for (std::size_t f : frames) {
        const pose& q = in.poses[f];
        const rotation_pose t(q);
        shown_frame s;
        s.index = f;
        s.result = det.collide(q);
        for (const auto& v : in.b.vertices()) s.b.push_back(t.apply<double>(v));
        s.p = t.apply<double>(in.b.centroid());
        s.candidates =
            edges_whose_extended_area_holds(options.shape, t.apply<exact_rational>(in.b.centroid()), cov, reach);
        shown.push_back(std::move(s));
    }
    return shown;
}

/// Where a polygon's edge with input number k is stored: the inverse of
/// polygon::source_edge.
std::vector<std::size_t> stored_edges(const polygon& shape) {
    std::vector<std::size_t> stored(shape.size());
    for (std::size_t i = 0; i < shape.size(); ++i) stored[shape.source_edge(i)] = i;
    return stored;
}

/// The mapping from scene coordinates to the SVG: the scene's box (padded,
/// its aspect kept within limits) is the nested viewport's view box; written
/// coordinates are taken relative to the box's centre and scaled by a power of
/// two to a width of 512 to 1024 units, so that every renderer sees moderate
/// numbers at any scale or offset; the group's scale(1,-1) flips y.
class view {
public:
    view(box scene, double pixel_width) : pixel_width_(pixel_width) {
        double w = scene.max_x - scene.min_x, h = scene.max_y - scene.min_y;
        const double pad = 0.04 * std::max(w, h);
        w += 2 * pad;
        h += 2 * pad;
        if (h > 1.25 * w) w = h / 1.25;
        if (h < 0.5 * w) h = 0.5 * w;
        cx_ = scene.min_x / 2 + scene.max_x / 2;
        cy_ = scene.min_y / 2 + scene.max_y / 2;
        k_ = std::ldexp(1.0, 9 - std::ilogb(w));
        width_ = w * k_;
        height_ = h * k_;
        pixel_height_ = std::round(pixel_width_ * h / w);
        diagonal_ = std::hypot(w, h);
    }

    double x(double scene_x) const { return (scene_x - cx_) * k_; }
    double y(double scene_y) const { return (scene_y - cy_) * k_; }
    double length(double scene_length) const { return scene_length * k_; }
    /// Units of the written coordinates per pixel.
    double per_pixel() const { return width_ / pixel_width_; }
    /// The diagonal of the view in scene units.
    double diagonal() const { return diagonal_; }
    /// Pixel position of a scene point within the scene's viewport.
    double pixel_x(double scene_x) const { return (x(scene_x) / width_ + 0.5) * pixel_width_; }
    double pixel_y(double scene_y) const { return (0.5 - y(scene_y) / height_) * pixel_height_; }
    double pixel_width() const { return pixel_width_; }
    double pixel_height() const { return pixel_height_; }
    std::string view_box() const {
        return svg::number(-width_ / 2) + " " + svg::number(-height_ / 2) + " " + svg::number(width_) + " " +
               svg::number(height_);
    }

private:
    double pixel_width_;
    double cx_ = 0, cy_ = 0, k_ = 1, width_ = 1, height_ = 1, pixel_height_ = 1, diagonal_ = 1;
};

/// How a layer is painted; stroke widths in pixels.
struct paint {
    const char* fill;
    double fill_opacity;
    const char* stroke;
    double stroke_pixels;
    double stroke_opacity = 1;
    bool dashed = false;
};

const paint cone_paint{"#5b7fb0", 0.07, "#5b7fb0", 0.6, 0.35};
const paint static_fill_paint{"#ececec", 1, "none", 0};
const paint positive_paint{"#3a78d8", 0.22, "#3a78d8", 0.6, 0.8};
const paint negative_paint{"#ef8a1a", 0.32, "#d86a00", 0.6, 0.9};
const paint flat_paint{"none", 0, "#777777", 1.2, 1, true};
const paint static_outline_paint{"none", 0, "#222222", 1.6};
const paint extended_paint{"#2e9e5b", 0.12, "#2e9e5b", 1, 0.9, true};
const paint moving_paint{"#8e5cc4", 0.25, "#5b2f91", 1.4};
const paint contained_paint{"#d62728", 0.55, "#5b2f91", 1.4};
const paint static_witness_paint{"none", 0, "#d62728", 5, 0.9};
const paint moving_witness_paint{"none", 0, "#7a0010", 2.4};

/// Sets the paint's attributes on `e`, `per_pixel` units to a pixel.
svg::element& painted(svg::element& e, const paint& p, double per_pixel) {
    e.attr("fill", p.fill);
    if (p.fill_opacity < 1) e.num("fill-opacity", p.fill_opacity, 2);
    e.attr("stroke", p.stroke);
    if (p.stroke_pixels > 0) e.num("stroke-width", p.stroke_pixels * per_pixel);
    if (p.stroke_opacity < 1) e.num("stroke-opacity", p.stroke_opacity, 2);
    if (p.dashed) e.attr("stroke-dasharray", svg::number(4 * per_pixel) + " " + svg::number(3 * per_pixel));
    e.attr("stroke-linejoin", "round").attr("stroke-linecap", "round");
    return e;
}

/// Greedy line filling: the parts joined by "; ", a line at most `width`
/// characters where the parts allow.
std::vector<std::string> filled_lines(const std::vector<std::string>& parts, std::size_t width) {
    std::vector<std::string> lines;
    std::string line;
    for (const std::string& part : parts) {
        if (!line.empty() && line.size() + 2 + part.size() > width) {
            lines.push_back(line + ";");
            line.clear();
        }
        line += (line.empty() ? "" : "; ") + part;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

std::string plural(std::size_t count, const std::string& what) {
    return std::to_string(count) + " " + what + (count == 1 ? "" : "s");
}

/// Builds the whole picture as text.
class picture {
public:
    picture(const render_options& o, const scene_input& in, const triangle_covering<exact_rational>& cov, double n,
            std::vector<shown_frame> frames, std::string first)
        : o_(o),
          in_(in),
          cov_(cov),
          n_(n),
          frames_(std::move(frames)),
          first_(std::move(first)),
          shape_(o.shape == "band" ? extended_area::band : extended_area::capsule),
          view_(scene_box(), static_cast<double>(o.width)) {}

    std::string text() {
        std::size_t bold = 0;  // the first lines, of the file names
        const std::vector<std::string> title = title_lines(bold);
        const double title_height = 12 + 18 * static_cast<double>(title.size());
        std::string scene = scene_layers();
        std::string legend;
        const double legend_height = legend_rows(title_height + view_.pixel_height(), legend);
        const double total = title_height + view_.pixel_height() + legend_height;

        std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
        s += svg::element("svg")
                 .attr("xmlns", "http://www.w3.org/2000/svg")
                 .num("width", view_.pixel_width())
                 .num("height", total)
                 .attr("viewBox", "0 0 " + svg::number(view_.pixel_width()) + " " + svg::number(total))
                 .attr("font-family", "DejaVu Sans, Arial, sans-serif")
                 .open();
        std::string joined_title;
        for (const std::string& line : title) joined_title += (joined_title.empty() ? "" : "\n") + line;
        s += svg::element("title").with_text(joined_title);
        s += svg::element("rect").attr("width", "100%").attr("height", "100%").attr("fill", "white").empty();
        for (std::size_t i = 0; i < title.size(); ++i)
            s += svg::element("text")
                     .attr("class", "title")
                     .num("x", 10)
                     .num("y", 22 + 18 * static_cast<double>(i))
                     .attr("font-size", i < bold ? "14" : "12.5")
                     .attr("font-weight", i < bold ? "bold" : "normal")
                     .with_text(title[i]);
        s += svg::element("svg")
                 .num("x", 0)
                 .num("y", title_height)
                 .num("width", view_.pixel_width())
                 .num("height", view_.pixel_height())
                 .attr("viewBox", view_.view_box())
                 .attr("overflow", "hidden")
                 .open();
        s += svg::element("defs").open() + svg::element("clipPath").attr("id", "scene-clip").open();
        s += svg::element("rect")
                 .attr("x", "-50%")
                 .attr("y", "-50%")
                 .attr("width", "100%")
                 .attr("height", "100%")
                 .empty();
        s += svg::close("clipPath") + svg::close("defs");
        s += svg::element("g")
                 .attr("class", "scene")
                 .attr("transform", "scale(1,-1)")
                 .attr("clip-path", "url(#scene-clip)")
                 .open();
        s += scene;
        s += svg::close("g") + svg::close("svg");
        s += labels(title_height);
        s += legend;
        s += svg::close("svg");
        return s;
    }

private:
    /// Everything the picture must show: A, B at the shown frames, the
    /// extended areas drawn.
    box scene_box() const {
        box b = in_.a.bounds();
        for (const shown_frame& f : frames_) {
            for (const auto& v : f.b) b.add(v);
            if (o_.no_extended) continue;
            for (std::size_t i : f.candidates) {
                const point<double>&u = in_.a.vertex(i), &v = in_.a.vertex(in_.a.next(i));
                const extended_area_outline area = outline_of_extended_area(shape_, u, v, n_);
                if (area.disc || area.strip || shape_ == extended_area::capsule) {
                    b.add({std::min(u.x, v.x) - n_, std::min(u.y, v.y) - n_});
                    b.add({std::max(u.x, v.x) + n_, std::max(u.y, v.y) + n_});
                }
                for (const auto& c : area.corners) b.add(c);
            }
        }
        return b;
    }

    std::vector<std::string> title_lines(std::size_t& bold) const {
        std::vector<std::string> lines;
        // Characters per line: the file names are in a larger bold face.
        const auto width = static_cast<std::size_t>(view_.pixel_width() / 7.2);
        const auto bold_width = static_cast<std::size_t>(view_.pixel_width() / 8.6);
        const std::vector<std::string> files = {
            "A: " + shown_name(o_.scene.static_path) + " (" + plural(in_.a.size(), "edge") + ")",
            "B: " + shown_name(o_.scene.moving_path) + " (" + plural(in_.b.size(), "edge") + ")"};
        for (const std::string& line : filled_lines(files, bold_width)) lines.push_back(line);
        bold = lines.size();
        std::vector<std::string> setting = {
            "poses: " + motion_of(o_.scene) + ", " + plural(in_.poses.size(), "frame"),
            std::string("extended area: ") + (shape_ == extended_area::band ? "band" : "capsule") +
                ", n = r_B + d = " + general(n_, 4) + " (d = " + general(o_.distance) + ")"};
        if (!first_.empty()) setting.push_back("first collision: " + first_);
        for (const std::string& line : filled_lines(setting, width)) lines.push_back(line);
        std::vector<std::string> shown;
        for (const shown_frame& f : frames_) {
            std::string what = "frame " + std::to_string(f.index) + ": ";
            if (!f.result.collides)
                what += "apart";
            else if (f.result.pairs.empty())
                what += "collides by containment";
            else
                what += "collides, " + plural(f.result.pairs.size(), "edge pair");
            shown.push_back(what + " (" + plural(f.candidates.size(), "candidate edge") + ")");
        }
        if (shown.empty()) shown.push_back("no frame shown");
        for (const std::string& line : filled_lines(shown, width)) lines.push_back(line);
        return lines;
    }

    /// Path data of a ring list: every ring of `vertices` (stored order of `shape`).
    svg::path_data rings(const polygon& shape, const std::vector<point<double>>& vertices) const {
        svg::path_data d;
        for (std::size_t r = 0; r < shape.ring_count(); ++r) {
            for (std::size_t i = shape.ring_begin(r); i < shape.ring_end(r); ++i) {
                const point<double>& v = vertices[i];
                if (i == shape.ring_begin(r))
                    d.move(view_.x(v.x), view_.y(v.y));
                else
                    d.line(view_.x(v.x), view_.y(v.y));
            }
            d.close();
        }
        return d;
    }

    svg::path_data polygon_path(const std::vector<point<double>>& corners) const {
        svg::path_data d;
        for (std::size_t i = 0; i < corners.size(); ++i) {
            if (i == 0)
                d.move(view_.x(corners[i].x), view_.y(corners[i].y));
            else
                d.line(view_.x(corners[i].x), view_.y(corners[i].y));
        }
        return d.close();
    }

    std::string segment(const point<double>& u, const point<double>& v, const paint& p, const std::string& cls,
                        std::size_t frame, std::size_t edge) const {
        svg::element e("line");
        e.attr("class", cls).index("data-frame", frame).index("data-edge", edge);
        e.num("x1", view_.x(u.x)).num("y1", view_.y(u.y)).num("x2", view_.x(v.x)).num("y2", view_.y(v.y));
        return painted(e, p, view_.per_pixel()).empty();
    }

    /// The influence cone of stored edge i: the sector from O between the
    /// rays through its ends (less than a half-turn), cut at twice the view's
    /// diagonal, where the viewport clips it; four chords follow the arc.
    std::string cone(std::size_t i) const {
        const point<double> o = in_.a.centroid();
        const point<double>&u = in_.a.vertex(i), &v = in_.a.vertex(in_.a.next(i));
        const point<double>& from = cov_.sigma(i) > 0 ? u : v;
        const point<double>& to = cov_.sigma(i) > 0 ? v : u;
        constexpr double two_pi = 6.283185307179586;
        const double start = std::atan2(from.y - o.y, from.x - o.x);
        double turn = std::atan2(to.y - o.y, to.x - o.x) - start;
        if (turn < 0) turn += two_pi;
        const double reach = 2 * view_.diagonal();
        std::vector<point<double>> corners{o};
        for (int k = 0; k <= 4; ++k) {
            const double angle = start + turn * k / 4;
            corners.push_back({o.x + reach * std::cos(angle), o.y + reach * std::sin(angle)});
        }
        svg::element e("path");
        e.attr("class", "cone").index("data-edge", in_.a.source_edge(i)).attr("d", polygon_path(corners).str());
        return painted(e, cone_paint, view_.per_pixel()).empty();
    }

    std::string triangle(std::size_t i) const {
        const int sigma = cov_.sigma(i);
        const paint& p = sigma > 0 ? positive_paint : sigma < 0 ? negative_paint : flat_paint;
        const char* cls = sigma > 0 ? "triangle positive" : sigma < 0 ? "triangle negative" : "triangle flat";
        svg::element e("path");
        e.attr("class", cls).index("data-edge", in_.a.source_edge(i));
        e.attr("d", polygon_path({in_.a.centroid(), in_.a.vertex(i), in_.a.vertex(in_.a.next(i))}).str());
        return painted(e, p, view_.per_pixel()).empty();
    }

    std::string extended(const shown_frame& f, std::size_t i) const {
        const point<double>&u = in_.a.vertex(i), &v = in_.a.vertex(in_.a.next(i));
        const extended_area_outline area = outline_of_extended_area(shape_, u, v, n_);
        svg::path_data d;
        if (area.disc) {
            // Two half-circles about u.
            d.move(view_.x(u.x + n_), view_.y(u.y));
            d.arc(view_.length(n_), true, view_.x(u.x - n_), view_.y(u.y));
            d.arc(view_.length(n_), true, view_.x(u.x + n_), view_.y(u.y)).close();
        } else if (area.strip) {
            const double reach = 2 * view_.diagonal();
            d = polygon_path(
                {{u.x - n_, u.y - reach}, {u.x + n_, u.y - reach}, {u.x + n_, u.y + reach}, {u.x - n_, u.y + reach}});
        } else if (shape_ == extended_area::band) {
            d = polygon_path(area.corners);
        } else {
            // The capsule: the straight sides, and about each end a half-turn
            // (as two quarter arcs) away from the edge.
            const auto& c = area.corners;
            const double r = view_.length(n_);
            const double len = std::hypot(v.x - u.x, v.y - u.y);
            const double tx = (v.x - u.x) / len * n_, ty = (v.y - u.y) / len * n_;
            d.move(view_.x(c[0].x), view_.y(c[0].y)).line(view_.x(c[1].x), view_.y(c[1].y));
            d.arc(r, false, view_.x(v.x + tx), view_.y(v.y + ty)).arc(r, false, view_.x(c[2].x), view_.y(c[2].y));
            d.line(view_.x(c[3].x), view_.y(c[3].y));
            d.arc(r, false, view_.x(u.x - tx), view_.y(u.y - ty))
                .arc(r, false, view_.x(c[0].x), view_.y(c[0].y))
                .close();
        }
        svg::element e("path");
        e.attr("class", "extended")
            .index("data-frame", f.index)
            .index("data-edge", in_.a.source_edge(i))
            .attr("d", d.str());
        return painted(e, extended_paint, view_.per_pixel()).empty();
    }

    std::string dot(const point<double>& c, double radius_pixels, const char* fill, const std::string& cls) const {
        return svg::element("circle")
            .attr("class", cls)
            .num("cx", view_.x(c.x))
            .num("cy", view_.y(c.y))
            .num("r", radius_pixels * view_.per_pixel())
            .attr("fill", fill)
            .attr("stroke", "white")
            .num("stroke-width", 0.8 * view_.per_pixel())
            .empty();
    }

    std::string scene_layers() const {
        const polygon& a = in_.a;
        std::string s;
        if (!o_.no_cones) {
            s += svg::element("g").attr("class", "cones").open();
            for (std::size_t i = 0; i < a.size(); ++i)
                if (cov_.sigma(i) != 0) s += cone(i);
            s += svg::close("g");
        }
        const svg::path_data a_path = rings(a, a.vertices());
        svg::element fill("path");
        fill.attr("class", "static-fill").attr("d", a_path.str()).attr("fill-rule", "nonzero");
        s += painted(fill, static_fill_paint, view_.per_pixel()).empty();
        if (!o_.no_triangles) {
            s += svg::element("g").attr("class", "triangles").open();
            for (std::size_t i = 0; i < a.size(); ++i) s += triangle(i);
            s += svg::close("g");
        }
        svg::element outline("path");
        outline.attr("class", "static-polygon").attr("d", a_path.str());
        s += painted(outline, static_outline_paint, view_.per_pixel()).empty();

        if (!o_.no_extended)
            for (const shown_frame& f : frames_)
                for (std::size_t i : f.candidates) s += extended(f, i);
        for (const shown_frame& f : frames_) {
            std::string pairs;
            for (const edge_pair& p : f.result.pairs)
                pairs +=
                    (pairs.empty() ? "" : ";") + std::to_string(p.static_edge) + ":" + std::to_string(p.moving_edge);
            const bool contained = f.result.collides && f.result.pairs.empty();
            svg::element e("path");
            e.attr("class", contained ? "moving-polygon contained" : "moving-polygon")
                .index("data-frame", f.index)
                .attr("data-collides", f.result.collides ? "1" : "0")
                .attr("data-pairs", pairs)
                .attr("d", rings(in_.b, f.b).str())
                .attr("fill-rule", "nonzero");
            s += painted(e, contained ? contained_paint : moving_paint, view_.per_pixel()).empty();
            s += dot(f.p, 2.4, moving_paint.stroke, "moving-centroid");
        }
        // The colliding pairs on top: each edge once, A's wide, B's narrow.
        const std::vector<std::size_t> a_stored = stored_edges(a), b_stored = stored_edges(in_.b);
        for (const shown_frame& f : frames_) {
            std::vector<std::size_t> statics, movings;
            for (const edge_pair& p : f.result.pairs) {
                statics.push_back(p.static_edge);
                movings.push_back(p.moving_edge);
            }
            for (auto* list : {&statics, &movings}) {
                std::sort(list->begin(), list->end());
                list->erase(std::unique(list->begin(), list->end()), list->end());
            }
            for (std::size_t k : statics) {
                const std::size_t i = a_stored[k];
                s += segment(a.vertex(i), a.vertex(a.next(i)), static_witness_paint, "witness static", f.index, k);
            }
            for (std::size_t k : movings) {
                const std::size_t j = b_stored[k];
                s += segment(f.b[j], f.b[in_.b.next(j)], moving_witness_paint, "witness moving", f.index, k);
            }
        }
        s += dot(a.centroid(), 3.5, "#111111", "centroid");
        return s;
    }

    /// "frame k" at each shown frame, in pixels: over B's box, else under it,
    /// right or left of it, the first of these places that no earlier label
    /// takes (judged by an estimate of the text's width); kept in the picture.
    std::string labels(double top) const {
        std::string s;
        std::vector<box> taken;  // the labels placed, in pixels
        for (const shown_frame& f : frames_) {
            const std::string text = "frame " + std::to_string(f.index) + (f.result.collides ? " (collides)" : "");
            const double w = 6.2 * static_cast<double>(text.size()), h = 12;
            box b;
            for (const auto& v : f.b) b.add({view_.pixel_x(v.x), view_.pixel_y(v.y)});
            const double mid_x = b.min_x / 2 + b.max_x / 2, mid_y = b.min_y / 2 + b.max_y / 2;
            // Each place as the label's box: left, top, right, bottom.
            const std::vector<box> places = {{mid_x - w / 2, b.min_y - 4 - h, mid_x + w / 2, b.min_y - 4},
                                             {mid_x - w / 2, b.max_y + 3, mid_x + w / 2, b.max_y + 3 + h},
                                             {b.max_x + 5, mid_y - h / 2, b.max_x + 5 + w, mid_y + h / 2},
                                             {b.min_x - 5 - w, mid_y - h / 2, b.min_x - 5, mid_y + h / 2}};
            box place = places.front();
            for (const box& candidate : places) {
                bool free = true;
                for (const box& t : taken)
                    free = free && (candidate.max_x < t.min_x || candidate.min_x > t.max_x ||
                                    candidate.max_y < t.min_y || candidate.min_y > t.max_y);
                if (free) {
                    place = candidate;
                    break;
                }
            }
            // Kept within the picture.
            const double dx = std::clamp(place.min_x, 2.0, std::max(2.0, view_.pixel_width() - 2 - w)) - place.min_x;
            const double dy = std::clamp(place.min_y, 2.0, std::max(2.0, view_.pixel_height() - 4 - h)) - place.min_y;
            place = {place.min_x + dx, place.min_y + dy, place.max_x + dx, place.max_y + dy};
            taken.push_back(place);
            s += svg::element("text")
                     .attr("class", "frame-label")
                     .index("data-frame", f.index)
                     .num("x", place.min_x, 1)
                     .num("y", top + place.max_y - 2, 1)
                     .attr("font-size", "11")
                     .attr("fill", f.result.collides ? "#a00010" : "#3d1f63")
                     .attr("stroke", "white")
                     .attr("stroke-width", "3")
                     .attr("paint-order", "stroke")
                     .with_text(text);
        }
        s += svg::element("text")
                 .attr("class", "centroid-label")
                 .num("x", view_.pixel_x(in_.a.centroid().x) + 7, 1)
                 .num("y", top + view_.pixel_y(in_.a.centroid().y) + 14, 1)
                 .attr("font-size", "11")
                 .attr("stroke", "white")
                 .attr("stroke-width", "3")
                 .attr("paint-order", "stroke")
                 .with_text("O");
        return s;
    }

    /// The legend below the scene, from `top`: one entry per layer drawn,
    /// filled into rows. Returns its height in pixels.
    double legend_rows(double top, std::string& out) const {
        struct entry {
            const paint* p;
            bool line;
            std::string label;
        };
        std::vector<entry> entries;
        const auto any_sign = [&](int sign) {
            for (std::size_t i = 0; i < cov_.size(); ++i)
                if (cov_.sigma(i) == sign) return true;
            return false;
        };
        entries.push_back({&static_outline_paint, false, "A (static)"});
        if (!o_.no_triangles) {
            entries.push_back({&positive_paint, false, "covering triangle (O, V_i, V_i+1), sign +1 (positive)"});
            entries.push_back({&negative_paint, false, "covering triangle, sign -1 (negative)"});
            if (any_sign(0)) entries.push_back({&flat_paint, true, "flat triangle, sign 0"});
        }
        if (!o_.no_cones) entries.push_back({&cone_paint, false, "influence cone of an edge (overlaps darker)"});
        entries.push_back({nullptr, false, "O: centroid of A"});
        if (!frames_.empty()) {
            if (!o_.no_extended)
                entries.push_back({&extended_paint, false,
                                   std::string("extended area (") +
                                       (shape_ == extended_area::band ? "band" : "capsule") + ") of a candidate edge"});
            entries.push_back({&moving_paint, false, "B at a frame (dot: its centroid)"});
            entries.push_back({&static_witness_paint, true, "colliding edge of A"});
            entries.push_back({&moving_witness_paint, true, "colliding edge of B"});
            bool contained = false;
            for (const shown_frame& f : frames_) contained = contained || (f.result.collides && f.result.pairs.empty());
            if (contained) entries.push_back({&contained_paint, false, "B colliding by containment alone"});
        }
        double x = 10, y = top + 10;
        const double row = 18;
        for (const entry& e : entries) {
            const double w = 30 + 6.4 * static_cast<double>(e.label.size()) + 14;
            if (x > 10 && x + w > view_.pixel_width() - 6) {
                x = 10;
                y += row;
            }
            if (e.p == nullptr) {
                out += svg::element("circle")
                           .num("cx", x + 11)
                           .num("cy", y + 6)
                           .num("r", 3.5)
                           .attr("fill", "#111111")
                           .empty();
            } else if (e.line) {
                svg::element l("line");
                l.num("x1", x + 2).num("y1", y + 6).num("x2", x + 22).num("y2", y + 6);
                out += painted(l, *e.p, 1).empty();
            } else {
                svg::element r("rect");
                r.num("x", x).num("y", y).num("width", 22).num("height", 12);
                out += painted(r, *e.p, 1).empty();
            }
            out += svg::element("text")
                       .attr("class", "legend")
                       .num("x", x + 30)
                       .num("y", y + 10.5)
                       .attr("font-size", "11.5")
                       .with_text(e.label);
            x += w;
        }
        return y + row + 6 - top;
    }

    const render_options& o_;
    const scene_input& in_;
    const triangle_covering<exact_rational>& cov_;
    double n_;
    std::vector<shown_frame> frames_;
    std::string first_;
    extended_area shape_;
    view view_;
};

/// Whether the path ends in ".svg", in any case, or is '-' (standard
/// output): render writes SVG only.
bool names_svg(const std::string& path) {
    if (is_standard_stream(path)) return true;
    if (path.size() < 4) return false;
    std::string end = path.substr(path.size() - 4);
    for (char& c : end) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return end == ".svg";
}

void run_render(const render_options& o) {
    if (!names_svg(o.out))
        throw invalid_input("--out " + o.out +
                            ": render writes SVG; give a file name ending in .svg, or '-' for "
                            "standard output");
    const scene_input in = read_scene(o.scene, o.out);
    detector_options options;
    options.distance = o.distance;
    options.shape = o.shape == "band" ? extended_area::band : extended_area::capsule;
    std::string first;
    const std::vector<std::size_t> frames = chosen_frames(o, in, options, first);

    // The covering the detector uses: from A's centroid, signs decided exactly.
    const triangle_covering<exact_rational> cov(in.a, in.a.centroid());
    const double n = moving_reach(bounding_radius(in.b, in.b.centroid()), o.distance);
    picture pic(o, in, cov, n, evaluate(in, frames, options, cov, n), first);
    write_output(o.out, pic.text());
}

}  // namespace

void register_render(CLI::App& app) {
    auto o = std::make_shared<render_options>();
    CLI::App* sub = app.add_subcommand(
        "render",
        "Draw a scene as one SVG file: the static polygon A with its covering triangles (by sign), its centroid and "
        "its influence cones; at each chosen frame the moving polygon B, the extended areas of A's candidate edges "
        "(those whose area holds B's centroid) and the colliding edge pairs found by the exact detector.");
    add_scene_options(sub, o->scene);
    sub->add_option("--distance", o->distance,
                    "Separation distance D: a frame collides when the polygons are at distance <= D; the extended "
                    "areas have length n = r_B + D")
        ->capture_default_str()
        ->check(finite_non_negative())
        ->type_name("D");
    sub->add_option("--extended-area", o->shape,
                    "Shape of the extended influence areas drawn: capsule or band (the paper's)")
        ->capture_default_str()
        ->check(CLI::IsMember({"capsule", "band"}))
        ->type_name("SHAPE");
    sub->add_option("--frames", o->frames,
                    "Frames to draw, numbered from 0, separated by commas (default: four spread evenly over the "
                    "poses and the first colliding frame)")
        ->type_name("LIST");
    sub->add_option("--out", o->out,
                    "The SVG file to write; it is replaced only when the whole picture is made ('-': standard "
                    "output, written once the picture is made)")
        ->required()
        ->type_name("FILE.svg");
    sub->add_option("--width", o->width, "Width of the picture in pixels")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{200}, std::size_t{20000}))
        ->type_name("PIXELS");
    sub->add_flag("--no-cones", o->no_cones, "Leave out the influence cones");
    sub->add_flag("--no-triangles", o->no_triangles, "Leave out the covering triangles");
    sub->add_flag("--no-extended", o->no_extended, "Leave out the extended areas");
    sub->callback([o] { run_render(*o); });
}

}  // namespace influence2d::cli
