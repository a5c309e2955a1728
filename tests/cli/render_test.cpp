// SPDX-License-Identifier: BSL-1.0
// `influence2d render`, run as a separate process: the SVG is well-formed XML,
// shows one covering triangle per edge of A with its sign, and at each frame
// the exact detector's answer and witness pairs; bad input leaves no file.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "influence2d/covering/covering.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"

namespace fs = std::filesystem;
using namespace test_process;

namespace {

/// One element of a parsed document: its name, attributes and text (entity
/// references decoded).
struct xml_element {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;

    std::string attribute(const std::string& key) const {
        const auto it = attributes.find(key);
        return it == attributes.end() ? std::string() : it->second;
    }
    /// Whether the class attribute lists `word`.
    bool has_class(const std::string& word) const {
        std::istringstream words(attribute("class"));
        for (std::string w; words >> w;)
            if (w == word) return true;
        return false;
    }
};

/// A strict check of XML well-formedness for what an SVG file holds: an
/// optional declaration, comments, one root element, matching start and end
/// tags, quoted attributes without repeats, no '<' in attribute values and
/// only the predefined or numeric entity references. Throws naming the offset
/// of the first problem; returns every element in document order.
class xml_reader {
public:
    explicit xml_reader(std::string text) : s_(std::move(text)) {}

    std::vector<xml_element> elements() {
        if (s_.compare(0, 5, "<?xml") == 0) {
            const std::size_t end = s_.find("?>");
            if (end == std::string::npos) fail("unterminated declaration");
            i_ = end + 2;
        }
        std::vector<std::size_t> open;  // indexes into out_ of the unclosed elements
        bool root_seen = false;
        while (i_ < s_.size()) {
            if (s_.compare(i_, 4, "<!--") == 0) {
                const std::size_t end = s_.find("-->", i_ + 4);
                if (end == std::string::npos) fail("unterminated comment");
                i_ = end + 3;
            } else if (s_.compare(i_, 2, "</") == 0) {
                i_ += 2;
                const std::string name = read_name();
                skip_space();
                expect('>');
                if (open.empty() || out_[open.back()].name != name) fail("end tag </" + name + "> does not match");
                open.pop_back();
            } else if (s_[i_] == '<') {
                ++i_;
                if (open.empty() && root_seen) fail("second root element");
                root_seen = true;
                xml_element e;
                e.name = read_name();
                for (;;) {
                    const bool space = skip_space();
                    if (s_.compare(i_, 2, "/>") == 0 || (i_ < s_.size() && s_[i_] == '>')) break;
                    if (!space) fail("attributes must be separated by space");
                    const std::string key = read_name();
                    skip_space();
                    expect('=');
                    skip_space();
                    if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\'')) fail("unquoted attribute value");
                    const char quote_char = s_[i_++];
                    const std::size_t end = s_.find(quote_char, i_);
                    if (end == std::string::npos) fail("unterminated attribute value");
                    const std::string raw = s_.substr(i_, end - i_);
                    if (raw.find('<') != std::string::npos) fail("'<' in an attribute value");
                    if (!e.attributes.emplace(key, decode(raw)).second) fail("repeated attribute " + key);
                    i_ = end + 1;
                }
                const bool empty = s_[i_] == '/';
                i_ += empty ? 2 : 1;
                out_.push_back(e);
                if (!empty) open.push_back(out_.size() - 1);
            } else {
                const std::size_t end = std::min(s_.find('<', i_), s_.size());
                const std::string raw = s_.substr(i_, end - i_);
                if (open.empty()) {
                    if (raw.find_first_not_of(" \t\r\n") != std::string::npos) fail("text outside the root element");
                } else {
                    out_[open.back()].text += decode(raw);
                }
                i_ = end;
            }
        }
        if (!open.empty()) fail("element <" + out_[open.back()].name + "> is not closed");
        if (!root_seen) fail("no root element");
        return out_;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("not well-formed at offset " + std::to_string(i_) + ": " + what);
    }
    bool skip_space() {
        const std::size_t start = i_;
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
        return i_ > start;
    }
    void expect(char c) {
        if (i_ >= s_.size() || s_[i_] != c) fail(std::string("expected '") + c + "'");
        ++i_;
    }
    std::string read_name() {
        const auto name_char = [](char c, bool first) {
            const auto u = static_cast<unsigned char>(c);
            return std::isalpha(u) || c == '_' || c == ':' || (!first && (std::isdigit(u) || c == '-' || c == '.'));
        };
        const std::size_t start = i_;
        while (i_ < s_.size() && name_char(s_[i_], i_ == start)) ++i_;
        if (i_ == start) fail("expected a name");
        return s_.substr(start, i_ - start);
    }
    std::string decode(const std::string& raw) const {
        static const std::map<std::string, std::string> named{
            {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
        std::string out;
        for (std::size_t k = 0; k < raw.size(); ++k) {
            if (raw[k] != '&') {
                out += raw[k];
                continue;
            }
            const std::size_t end = raw.find(';', k);
            if (end == std::string::npos) fail("'&' without ';'");
            const std::string ref = raw.substr(k + 1, end - k - 1);
            if (named.count(ref))
                out += named.at(ref);
            else if (ref.size() > 1 && ref[0] == '#' && ref.find_first_not_of("0123456789", 1) == std::string::npos)
                out += '?';
            else
                fail("unknown entity &" + ref + ";");
            k = end;
        }
        return out;
    }

    std::string s_;
    std::size_t i_ = 0;
    std::vector<xml_element> out_;
};

std::vector<xml_element> parse_svg(const fs::path& file) {
    const std::string text = slurp(file);
    REQUIRE(!text.empty());
    std::vector<xml_element> all;
    REQUIRE_NOTHROW(all = xml_reader(text).elements());
    REQUIRE(all.front().name == "svg");
    return all;
}

/// The elements of class `cls`, for frame `frame` when given.
std::vector<xml_element> of_class(const std::vector<xml_element>& all, const std::string& cls,
                                  const std::string& frame = "") {
    std::vector<xml_element> found;
    for (const xml_element& e : all)
        if (e.has_class(cls) && (frame.empty() || e.attribute("data-frame") == frame)) found.push_back(e);
    return found;
}

std::set<std::string> attribute_set(const std::vector<xml_element>& elements, const std::string& key) {
    std::set<std::string> values;
    for (const xml_element& e : elements) values.insert(e.attribute(key));
    return values;
}

/// "2:0;2:1" -> {"2:0", "2:1"}
std::set<std::string> pair_set(const std::string& list) {
    std::set<std::string> pairs;
    std::istringstream in(list);
    for (std::string p; std::getline(in, p, ';');)
        if (!p.empty()) pairs.insert(p);
    return pairs;
}

std::string all_text(const std::vector<xml_element>& all, const std::string& cls) {
    std::string text;
    for (const xml_element& e : of_class(all, cls)) text += e.text + "\n";
    return text;
}

const char* const square4 = "POLYGON((0 0,4 0,4 4,0 4,0 0))\n";
const char* const square2 = "POLYGON((0 0,2 0,2 2,0 2,0 0))\n";
// Apart; corner on corner (4,4); B's bottom edge on A's top edge; B inside A
// without contact; B 0.25 right of A, its centroid within r_B of A's right
// edge only.
const char* const five_poses = "tx,ty,theta\n10,10,0\n4,4,0\n1,4,0\n1,1,0\n4.25,1,0\n";

std::string render_args(const fs::path& a, const fs::path& b) {
    return "render --static " + quote(a.string()) + " --moving " + quote(b.string());
}

/// The two squares and the five poses above, in a fresh directory.
struct squares {
    temp_dir dir;
    fs::path a = dir.file("A.wkt", square4);
    fs::path b = dir.file("B.wkt", square2);
    fs::path poses = dir.file("poses.csv", five_poses);

    /// `render` on them, writing `out`, with `more` options.
    run_result render(const fs::path& out, const std::string& more) const {
        return run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()) + " " + more + " --out " +
                                quote(out.string()));
    }
};

}  // namespace

TEST_CASE("render: the well-formedness check rejects broken documents", "[render]") {
    CHECK_NOTHROW(xml_reader("<?xml version=\"1.0\"?>\n<a x=\"1 &amp; 2\"><b/>t&lt;<!-- c --></a>\n").elements());
    CHECK(xml_reader("<a x='&quot;'>&#38;</a>").elements().front().attribute("x") == "\"");
    for (const char* bad : {"<a><b></a></b>", "<a>&</a>", "<a>x & y;</a>", "<a x=\"1\" x=\"2\"/>", "<a/><b/>", "<a>",
                            "<a x=1/>", "<a x=\"<\"/>", "<a x=\"1\"y=\"2\"/>", "text<a/>", "<a>&nbsp;</a>", ""}) {
        INFO(bad);
        CHECK_THROWS(xml_reader(bad).elements());
    }
}

TEST_CASE("render: each frame shows the exact detector's answer and witness pairs", "[render]") {
    const squares s;
    const auto& [dir, a, b, poses] = s;
    const auto svg = dir / "scene.svg";
    const auto r = s.render(svg, "--frames 0,1,2,3,4");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(!fs::exists(svg.string() + ".tmp"));
    const auto all = parse_svg(svg);

    // The reference: `collide` in exact arithmetic with witnesses.
    const auto frames_csv = dir / "frames.csv";
    const auto c =
        run_cli(dir, "collide --static " + quote(a.string()) + " --moving " + quote(b.string()) + " --poses " +
                         quote(poses.string()) + " --number-type exact --witness --out " + quote(frames_csv.string()));
    REQUIRE(c.exit_code == 0);
    const auto lines = lines_of(slurp(frames_csv));
    REQUIRE(lines.size() == 6);
    for (std::size_t f = 0; f < 5; ++f) {
        const std::string frame = std::to_string(f);
        INFO("frame " << frame);
        const std::string line = lines[f + 1];  // frame,collides,edges
        const std::string collides = line.substr(line.find(',') + 1, 1);
        const std::set<std::string> pairs = pair_set(line.substr(line.rfind(',') + 1));
        const auto moving = of_class(all, "moving-polygon", frame);
        REQUIRE(moving.size() == 1);
        CHECK(moving[0].attribute("data-collides") == collides);
        CHECK(pair_set(moving[0].attribute("data-pairs")) == pairs);
        // The highlighted edges are those of the pairs, on both polygons.
        std::set<std::string> statics, movings;
        for (const std::string& p : pairs) {
            statics.insert(p.substr(0, p.find(':')));
            movings.insert(p.substr(p.find(':') + 1));
        }
        const auto witness = of_class(all, "witness", frame);
        CHECK(attribute_set(of_class(witness, "static"), "data-edge") == statics);
        CHECK(attribute_set(of_class(witness, "moving"), "data-edge") == movings);
        CHECK(of_class(witness, "static").size() == statics.size());
        CHECK(of_class(witness, "moving").size() == movings.size());
    }
    // The answers themselves, as the catalogue gives them.
    CHECK(pair_set(of_class(all, "moving-polygon", "1")[0].attribute("data-pairs")) ==
          std::set<std::string>{"1:0", "1:3", "2:0", "2:3"});
    CHECK(pair_set(of_class(all, "moving-polygon", "2")[0].attribute("data-pairs")) ==
          std::set<std::string>{"2:0", "2:1", "2:3"});
    // Apart: nothing highlighted; containment alone: B marked, no pair.
    CHECK(of_class(all, "moving-polygon", "0")[0].attribute("data-collides") == "0");
    CHECK(of_class(all, "witness", "0").empty());
    CHECK(of_class(all, "moving-polygon", "4")[0].attribute("data-collides") == "0");
    CHECK(of_class(all, "witness", "4").empty());
    CHECK(of_class(all, "moving-polygon", "3")[0].attribute("data-collides") == "1");
    CHECK(of_class(all, "moving-polygon", "3")[0].has_class("contained"));
    CHECK(of_class(all, "witness", "3").empty());
    CHECK(of_class(all, "contained").size() == 1);
    // Candidate edges: none far away; at frame 4 A's right edge only.
    CHECK(of_class(all, "extended", "0").empty());
    CHECK(attribute_set(of_class(all, "extended", "4"), "data-edge") == std::set<std::string>{"1"});
    // The title says what each frame is.
    const std::string title = all_text(all, "title");
    CHECK(title.find("frame 0: apart") != std::string::npos);
    CHECK(title.find("frame 1: collides, 4 edge pairs") != std::string::npos);
    CHECK(title.find("frame 3: collides by containment") != std::string::npos);
    // The scene is drawn in a computed view box, flipped in y.
    bool flipped = false, view_box = false;
    for (const xml_element& e : all) {
        flipped = flipped || (e.has_class("scene") && e.attribute("transform") == "scale(1,-1)");
        view_box = view_box || (e.name == "svg" && &e != &all.front() && !e.attribute("viewBox").empty());
    }
    CHECK(flipped);
    CHECK(view_box);
}

TEST_CASE("render: one covering triangle per edge of A, classed by its sign", "[render]") {
    // Concave with its centroid outside; an edge on a line through the
    // centroid (a flat triangle); a hole.
    std::set<std::string> kinds;
    for (const char* wkt : {"POLYGON((0 0,8 0,8 2,2 2,2 6,8 6,8 8,0 8,0 0))",
                            "POLYGON((0 0,4 0,4 1,6 1,6 2,4 2,4 4,0 4,0 3,-2 3,-2 2,0 2,0 0))",
                            "POLYGON((0 0,8 0,8 8,0 8,0 0),(5 5,5 7,7 7,7 5,5 5))"}) {
        INFO(wkt);
        const temp_dir dir;
        const auto a = dir.file("A.wkt", wkt);
        const auto b = dir.file("B.wkt", square2);
        const auto poses = dir.file("poses.csv", "tx,ty,theta\n20,0,0\n");
        const auto svg = dir / "a.svg";
        const auto r =
            run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()) + " --out " + quote(svg.string()));
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        const auto all = parse_svg(svg);

        const influence2d::polygon shape = influence2d::read_wkt(wkt);
        const influence2d::triangle_covering<influence2d::exact_rational> cov(shape, shape.centroid());
        std::map<std::string, std::string> expected;  // input edge -> sign class
        std::size_t cones = 0;
        for (std::size_t i = 0; i < shape.size(); ++i) {
            const int s = cov.sigma(i);
            expected[std::to_string(shape.source_edge(i))] = s > 0 ? "positive" : s < 0 ? "negative" : "flat";
            cones += s != 0 ? 1 : 0;
        }
        std::map<std::string, std::string> drawn;
        for (const xml_element& t : of_class(all, "triangle")) {
            const std::string cls = t.has_class("positive")   ? "positive"
                                    : t.has_class("negative") ? "negative"
                                    : t.has_class("flat")     ? "flat"
                                                              : "none";
            CHECK(drawn.emplace(t.attribute("data-edge"), cls).second);
        }
        CHECK(of_class(all, "triangle").size() == shape.size());
        CHECK(drawn == expected);
        CHECK(of_class(all, "cone").size() == cones);
        for (const auto& [edge, cls] : expected) kinds.insert(cls);
        // The legend says which colour is which.
        const std::string legend = all_text(all, "legend");
        CHECK(legend.find("positive") != std::string::npos);
        CHECK(legend.find("negative") != std::string::npos);
    }
    // The scenes have triangles of every kind.
    CHECK(kinds == std::set<std::string>{"positive", "negative", "flat"});
}

TEST_CASE("render: default frames are spread over the trajectory and include the first collision", "[render]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    const auto b = dir.file("B.wkt", "POLYGON((0 0,2 0,1 2,0 0))");
    const auto svg = dir / "linear.svg";
    const auto r =
        run_cli(dir, render_args(a, b) + " --trajectory linear --trajectory-frames 40 --out " + quote(svg.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto all = parse_svg(svg);

    const auto c = run_cli(dir, "collide --static " + quote(a.string()) + " --moving " + quote(b.string()) +
                                    " --trajectory linear --trajectory-frames 40 --number-type exact");
    REQUIRE(c.exit_code == 0);
    const std::string key = "first collision: frame ";
    const std::size_t at = c.out.find(key);
    REQUIRE(at != std::string::npos);
    const std::string first = c.out.substr(at + key.size(), c.out.find('\n', at) - at - key.size());
    const std::set<std::string> expected{"0", "10", "20", "30", first};
    CHECK(attribute_set(of_class(all, "moving-polygon"), "data-frame") == expected);
    CHECK(of_class(all, "moving-polygon", first)[0].attribute("data-collides") == "1");
    CHECK(all_text(all, "title").find("first collision: frame " + first) != std::string::npos);
}

TEST_CASE("render: layers can be left out, and the band has no round ends", "[render]") {
    const squares s;
    const auto svg = s.dir / "layers.svg";
    auto r = s.render(svg, "--frames 4 --no-cones --no-triangles --no-extended --width 400");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    auto all = parse_svg(svg);
    CHECK(of_class(all, "cone").empty());
    CHECK(of_class(all, "triangle").empty());
    CHECK(of_class(all, "extended").empty());
    CHECK(of_class(all, "moving-polygon").size() == 1);
    CHECK(all.front().attribute("width") == "400");

    for (const char* shape : {"capsule", "band"}) {
        r = s.render(svg, std::string("--frames 4 --extended-area ") + shape);
        REQUIRE(r.exit_code == 0);
        all = parse_svg(svg);
        CHECK(of_class(all, "cone").size() == 4);
        CHECK(of_class(all, "triangle", "").size() == 4);
        const auto extended = of_class(all, "extended", "4");
        REQUIRE(extended.size() == 1);
        const bool arcs = extended[0].attribute("d").find('A') != std::string::npos;
        CHECK(arcs == (std::string(shape) == "capsule"));
    }
}

TEST_CASE("render: file names are escaped in the title", "[render]") {
    const temp_dir dir;
    const std::string name = "a&b<c>'\".wkt";
    const auto a = dir.file(name, square4);
    const auto b = dir.file("B.wkt", square2);
    const auto poses = dir.file("poses.csv", five_poses);
    const auto svg = dir / "escaped.svg";
    const auto r =
        run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()) + " --out " + quote(svg.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto all = parse_svg(svg);
    CHECK(all_text(all, "title").find(name) != std::string::npos);
}

TEST_CASE("render: bad input exits 2 and leaves no file", "[render]") {
    const squares s;
    const auto& [dir, a, b, poses] = s;
    const auto broken = dir.file("broken.wkt", "POLYGON((0 0,1 0,1 1,0 0");
    const auto bad_poses = dir.file("bad.csv", "tx,ty,theta\n1,2,x\n");
    const auto svg = dir / "out.svg";
    const auto no_file = [&] {
        CHECK(!fs::exists(svg));
        CHECK(!fs::exists(svg.string() + ".tmp"));
    };

    auto r =
        run_cli(dir, render_args(broken, b) + " --poses " + quote(poses.string()) + " --out " + quote(svg.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("broken.wkt") != std::string::npos);
    no_file();

    r = run_cli(dir, render_args(a, b) + " --poses " + quote(bad_poses.string()) + " --out " + quote(svg.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("bad.csv: line 2") != std::string::npos);
    no_file();

    r = s.render(svg, "--frames 0,7");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("frame 7") != std::string::npos);
    CHECK(r.err.find("5 frames") != std::string::npos);
    no_file();
    r = s.render(svg, "--frames 99999999999999999999999");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("frame 99999999999999999999999 is out of range") != std::string::npos);
    no_file();
    for (const char* list : {"1,x", "-1", "1.5", "1,,2", "1,", ","}) {
        INFO(list);
        r = s.render(svg, std::string("--frames=") + list);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("is not a frame number") != std::string::npos);
        no_file();
    }

    r = run_cli(dir, render_args(a, b) + " --trajectory linear --trajectory-frames 10 --frames 10 --out " +
                         quote(svg.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("frame 10") != std::string::npos);
    CHECK(r.err.find("10 frames") != std::string::npos);
    no_file();

    // render writes SVG only: another file name is refused, nothing written.
    const auto png = dir / "picture.png";
    r = run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()) + " --out " + quote(png.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("render writes SVG") != std::string::npos);
    CHECK(!fs::exists(png));

    r = run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()));  // no --out
    CHECK(r.exit_code == 2);
    r = run_cli(dir, render_args(a, b) + " --poses " + quote(poses.string()) + " --out " +
                         quote((dir / "missing" / "x.svg").string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("does not exist") != std::string::npos);

    // A file already there is left as it was.
    const auto kept = dir.file("kept.svg", "old");
    r = run_cli(dir, render_args(a, broken) + " --poses " + quote(poses.string()) + " --out " + quote(kept.string()));
    CHECK(r.exit_code == 2);
    CHECK(slurp(kept) == "old");
}
