// IES LM-63 reader.
//
// A primer on the format (LM-63-2002 / -2019; older versions differ where noted):
//   line 1       version tag: "IESNA:LM-63-1995", "IESNA:LM-63-2002", "IES:LM-63-2019", "IESNA91";
//                LM-63-1986 has no tag and starts straight with free text.
//   keywords     "[TEST] ...", "[MANUFAC] ...", "[MORE]" continues the previous keyword;
//                1986 files have free text instead.
//   TILT=        NONE | INCLUDE (4 items follow) | <file name> (the 4 items are in that file):
//                lamp-to-luminaire geometry, number of pairs, angles, multiplying factors.
//   then numbers, separated by blanks or commas and wrapped across lines any way:
//     lamps, lumens per lamp (-1 = absolute), candela multiplier, #vertical, #horizontal,
//     photometric type (1 = C, 2 = B, 3 = A), units (1 = feet, 2 = metres), width, length, height
//     ballast factor, ballast-lamp photometric factor (<= 1995; "future use" in 2002; file
//     generation type in 2019, not a factor), input watts
//     vertical angles, horizontal angles, then for each horizontal angle all vertical values.
//
// Policy (after Radiance's ies2rad: "be permissive, accepting reasonable deviations"): unknown
// keywords, non-standard tags (IESNA95), odd bytes and ragged wrapping are accepted; anything
// that would change the numbers (counts, non-numeric or negative values, angles that do not
// increase or fit no symmetry) is an error naming the file, the line and what was expected.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "photometry/file_warnings.h"
#include "photometry/opening.h"
#include "photometry/readers.h"
#include "photometry/source_text.h"
#include "photometry/symmetry.h"
#include "photometry/table_warnings.h"
#include "photometry/tabular_distribution.h"
#include "photometry/tilt.h"
#include "photometry/tilt_file.h"
#include "util/error.h"

namespace luxgrid::photometry {

namespace {

constexpr double kFeetToMetres = 0.3048;

struct Version {
  int year = 1986;
  std::string tag;  // as written, "" for 1986
  bool has_tag_line = false;
};

std::string_view first_word(std::string_view s) { return s.substr(0, s.find_first_of(" \t")); }

Version detect_version(std::string_view first, std::vector<std::string>& warnings,
                       const std::string& name) {
  Version v;
  const std::string_view t = trim(first);
  std::string upper(t);
  for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (upper.rfind("IESNA", 0) == 0 || upper.rfind("IES:", 0) == 0) {
    v.has_tag_line = true;
    v.tag = std::string(t);
    const auto pos = upper.find("LM-63-");
    if (pos != std::string::npos && pos + 10 <= upper.size()) {
      v.year = std::atoi(upper.substr(pos + 6, 4).c_str());
    } else if (upper.rfind("IESNA91", 0) == 0) {
      v.year = 1991;
    } else if (upper.rfind("IESNA95", 0) == 0) {
      v.year = 1995;
      warnings.push_back(name + ":1: non-standard version tag " + quote_word(first_word(t)) +
                         "; read as LM-63-1995");
    } else {
      v.year = 1995;
      warnings.push_back(name + ":1: unknown version tag " + quote_word(first_word(t)) +
                         "; read as LM-63-1995");
    }
    if (v.year != 1991 && v.year != 1995 && v.year != 2002 && v.year != 2019) {
      warnings.push_back(name + ":1: unknown LM-63 year in " + quote_word(first_word(t)) +
                         "; read with the rules of the nearest version");
      v.year = v.year < 1991 ? 1991 : v.year < 1995 ? 1995 : v.year < 2002 ? 2002 : 2019;
    }
  }
  return v;
}

bool is_tilt_line(std::string_view line, std::string& value) {
  std::string_view t = trim(line);
  if (t.size() < 4) return false;
  std::string head(t.substr(0, 4));
  for (char& ch : head) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (head != "TILT") return false;
  t.remove_prefix(4);
  t = trim(t);
  if (t.empty() || t.front() != '=') return false;
  t.remove_prefix(1);
  value = std::string(trim(t));
  return true;
}

// Reads numbers one at a time from the token stream, remembering where the last one was.
class Numbers {
 public:
  Numbers(const SourceText& src, std::vector<Token> tokens, int after_line)
      : src_(src), tokens_(std::move(tokens)), after_line_(after_line) {}

  bool done() const { return next_ >= tokens_.size(); }
  std::size_t left() const { return tokens_.size() - next_; }
  const Token& peek() const { return tokens_[next_]; }
  int last_line() const { return next_ > 0 ? tokens_[next_ - 1].line : after_line_; }
  int end_line() const {
    return tokens_.empty() ? std::max(after_line_, src_.line_count()) : tokens_.back().line;
  }
  const Token& take(const std::string& what) {
    if (done()) src_.fail(end_line(), "expected " + what + ", found the end of the file");
    return tokens_[next_++];
  }
  double number(const std::string& what) { return parse_number(src_, take(what), what); }
  long count(const std::string& what, long lo, long hi) {
    return parse_count(src_, take(what), what, lo, hi);
  }

 private:
  const SourceText& src_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  int after_line_;
};

// Reads `n` strictly increasing angles within [lo, hi].
std::vector<double> read_angles(const SourceText& src, Numbers& in, long n, const char* what,
                                double lo, double hi) {
  std::vector<double> a;
  a.reserve(static_cast<std::size_t>(std::min<long>(n, static_cast<long>(in.left()))));
  for (long k = 0; k < n; ++k) {
    if (in.done())
      src.fail(in.end_line(), "expected " + std::to_string(n) + " " + what + " angles, found " +
                                  std::to_string(k) + " (the file ends)");
    const Token& t = in.take(std::string(what) + " angle");
    const double v = parse_number(src, t, std::string(what) + " angle " + std::to_string(k + 1));
    if (!a.empty() && !(v > a.back())) {
      if (k == n - 1 || (v <= a.front()))
        // The list restarted (typically the next list's 0): the count in the header is too high.
        src.fail(t.line, "expected " + std::to_string(n) + " " + what + " angles, found " +
                             std::to_string(k) + " (then " + format_number(v) +
                             ", which does not increase)");
      src.fail(t.line, std::string(what) + " angles must increase: " + format_number(v) +
                           " follows " + format_number(a.back()));
    }
    if (v < lo - 1e-9 || v > hi + 1e-9)
      src.fail(t.line, "expected " + std::string(what) + " angles between " + format_number(lo) +
                           " and " + format_number(hi) + ", found " + format_number(v));
    a.push_back(v);
  }
  return a;
}

TiltTable read_tilt_items(const SourceText& src, Numbers& in, std::string source) {
  TiltTable t;
  t.source = std::move(source);
  t.lamp_to_luminaire_geometry =
      static_cast<int>(in.count("the TILT lamp-to-luminaire geometry (1, 2 or 3)", 1, 3));
  const long n = in.count("the number of TILT angle/factor pairs", 1, kMaxTiltPairs);
  t.angle_deg = read_angles(src, in, n, "TILT", -180.0, 180.0);
  for (long k = 0; k < n; ++k) {
    const Token& tok = in.take("TILT multiplying factor");
    const double f = parse_number(src, tok, "TILT multiplying factor " + std::to_string(k + 1));
    if (f < 0 || f > kMaxTiltFactor)
      src.fail(tok.line, "expected a TILT multiplying factor from 0 to " +
                             format_number(kMaxTiltFactor) + ", found " + format_number(f));
    t.factor.push_back(f);
  }
  return t;
}

}  // namespace

Photometry read_ies(std::string_view bytes, const std::string& name,
                    const std::filesystem::path& tilt_dir, const LoadOptions& options) {
  const SourceText src(bytes, name);
  Photometry p;
  p.source = name;
  if (src.line_count() == 0 || trim(bytes).empty()) src.fail(0, "file is empty");

  const Version ver = detect_version(src.line(1), p.warnings, name);
  p.version = "LM-63-" + std::to_string(ver.year);
  p.format = "IES " + p.version;
  if (ver.has_tag_line) p.keywords["_VERSION_TAG"] = clean_text(ver.tag);

  // Keyword lines up to TILT=.
  int tilt_line = 0;
  std::string tilt_value;
  std::string last_key;
  for (int n = ver.has_tag_line ? 2 : 1; n <= src.line_count(); ++n) {
    const std::string_view raw = src.line(n);
    if (is_tilt_line(raw, tilt_value)) {
      tilt_line = n;
      break;
    }
    const std::string_view t = trim(raw);
    if (t.empty()) continue;
    std::string key, value;
    if (ver.year >= 1991 && t.front() == '[' && t.find(']') != std::string_view::npos) {
      const auto close = t.find(']');
      key = clean_text(t.substr(1, close - 1));
      value = clean_text(t.substr(close + 1));
    } else {
      key = "TEXT";  // LM-63-1986 free text, or a stray line (ledalite's SCCSid)
      value = clean_text(t);
    }
    if (key == "MORE" && !last_key.empty()) {
      p.keywords[last_key] += "\n" + value;
      continue;
    }
    auto [it, inserted] = p.keywords.emplace(key, value);
    if (!inserted) it->second += "\n" + value;
    last_key = key;
  }
  if (tilt_line == 0) {
    src.fail(src.line_count(), "expected a TILT= line before the photometric data, found none in " +
                                   std::to_string(src.line_count()) + " lines");
  }

  Numbers in(src, src.tokens_from(tilt_line + 1), tilt_line);
  std::string tilt_upper = tilt_value;
  for (char& ch : tilt_upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (tilt_upper == "INCLUDE") {
    p.tilt = std::make_shared<TiltTable>(read_tilt_items(src, in, "INCLUDE"));
  } else if (tilt_upper != "NONE") {
    if (tilt_value.empty())
      src.fail(tilt_line, "expected NONE, INCLUDE or a file name after TILT=");
    std::filesystem::path tilt_path;
    const std::string tilt_bytes =
        read_tilt_file(src, tilt_line, tilt_value, tilt_dir, options.allowed_root, tilt_path);
    try {
      const SourceText tilt_src(tilt_bytes, tilt_path.string());
      Numbers tin(tilt_src, tilt_src.tokens_from(1), 0);
      p.tilt = std::make_shared<TiltTable>(read_tilt_items(tilt_src, tin, tilt_path.string()));
    } catch (const InputError& e) {
      // Both places: the IES line that named the file, then the line inside it.
      src.fail(tilt_line, "TILT file '" + tilt_value + "': " + e.what());
    }
  }

  // Line 10.
  const long lamps = in.count("the number of lamps", 0, 1000000);
  const Token& lumens_tok = in.take("lumens per lamp");
  const double lumens = parse_number(src, lumens_tok, "lumens per lamp");
  if (lumens > 0)
    check_lamp_flux(
        src, lumens_tok.line,
        "the lamp flux (" + std::to_string(lamps) + " x " + format_number(lumens) + " lm)",
        lumens * static_cast<double>(lamps));
  const Token& mult_tok = in.take("candela multiplier");
  const double multiplier = parse_number(src, mult_tok, "candela multiplier");
  if (!(multiplier > 0))
    src.fail(mult_tok.line,
             "expected a candela multiplier > 0, found " + format_number(multiplier));
  const long nv = in.count("the number of vertical angles", 1, kMaxAngles);
  const int nv_line = in.last_line();
  const long nh = in.count("the number of horizontal angles", 1, kMaxAngles);
  const int nh_line = in.last_line();
  if (nv * nh > kMaxValues)
    src.fail(in.last_line(), "expected at most " + std::to_string(kMaxValues) +
                                 " candela values, the header claims " + std::to_string(nv) +
                                 " x " + std::to_string(nh));
  const long type = in.count("the photometric type (1 = C, 2 = B, 3 = A)", 1, 3);
  const long units = in.count("the units type (1 = feet, 2 = metres)", 1, 2);
  const double unit = units == 1 ? kFeetToMetres : 1.0;
  const double width = in.number("the luminous opening width");
  check_opening_size(src, in.last_line(), "the luminous opening width", width * unit);
  const double length = in.number("the luminous opening length");
  check_opening_size(src, in.last_line(), "the luminous opening length", length * unit);
  const double height = in.number("the luminous opening height");
  check_opening_size(src, in.last_line(), "the luminous opening height", height * unit);
  // Line 11.
  const Token& bf_tok = in.take("ballast factor");
  const double ballast = parse_number(src, bf_tok, "ballast factor");
  if (!(ballast > 0))
    src.fail(bf_tok.line, "expected a ballast factor > 0, found " + format_number(ballast));
  const Token& f2_tok =
      in.take(ver.year >= 2019 ? "file generation type" : "ballast-lamp photometric factor");
  const double f2 = parse_number(src, f2_tok, "line 11 second value");
  const double watts = in.number("input watts");

  // One vertical angle spans no solid angle: no flux, nothing to interpolate. Types A and B have
  // no rotational symmetry either, so they need two horizontal angles as well (type C: one
  // horizontal angle is a rotationally symmetric file).
  const char* type_name = type == 1 ? "C" : type == 2 ? "B" : "A";
  if (nv < 2)
    src.fail(nv_line, "expected at least 2 vertical angles for a type " + std::string(type_name) +
                          " file, found " + std::to_string(nv) +
                          " (one angle describes no distribution)");
  if (nh < 2 && type != 1)
    src.fail(nh_line, "expected at least 2 horizontal angles for a type " + std::string(type_name) +
                          " file, found " + std::to_string(nh) +
                          " (types A and B have no rotational symmetry)");

  // Factors: multiplier x ballast factor, and the ballast-lamp factor where it is one.
  double factor = multiplier * ballast;
  if (ver.year <= 1995) {
    if (!(f2 > 0))
      src.fail(f2_tok.line,
               "expected a ballast-lamp photometric factor > 0, found " + format_number(f2));
    factor *= f2;
  } else if (ver.year == 2002 && f2 != 1.0) {
    p.warnings.push_back(src.where(f2_tok.line) + ": line 11 second value " + format_number(f2) +
                         " is 'future use' in LM-63-2002; ignored");
  } else if (ver.year >= 2019) {
    p.keywords["_FILE_GENERATION_TYPE"] = format_number(f2);
  }
  // Every factor at once, with the largest TILT factor the luminaire may be tilted into.
  const double max_tilt =
      p.tilt ? *std::max_element(p.tilt->factor.begin(), p.tilt->factor.end()) : 1.0;
  if (!std::isfinite(factor) || !(factor <= kMaxIntensity_cd))
    src.fail(bf_tok.line, "expected the candela multiplier x ballast factor" +
                              std::string(ver.year <= 1995 ? " x ballast-lamp factor" : "") +
                              " to be at most " + format_number(kMaxIntensity_cd) + ", found " +
                              format_number(factor));
  p.candela_multiplier = factor;

  // Angles and values.
  const auto ptype = type == 1   ? PhotometricType::C
                     : type == 2 ? PhotometricType::B
                                 : PhotometricType::A;
  p.photometric_type = ptype;
  StoredPlanes planes;
  const bool c = ptype == PhotometricType::C;
  // Ranges: type C gamma 0..180 and C 0..360; type B: V (B plane) -180..180, H (in the plane,
  // from the axis) -90..90; type A: H (about the vertical axis) -180..180, V (elevation) -90..90.
  const bool b = ptype == PhotometricType::B;
  const double v_lim = c ? 180.0 : b ? 180.0 : 90.0;
  const double h_lim = c ? 360.0 : b ? 90.0 : 180.0;
  planes.v_deg = read_angles(src, in, nv, "vertical", c ? 0.0 : -v_lim, v_lim);
  const int h_line = in.done() ? in.end_line() : in.peek().line;
  planes.h_deg = read_angles(src, in, nh, "horizontal", c ? 0.0 : -h_lim, h_lim);
  const long total = nv * nh;
  if (static_cast<long>(in.left()) < total)
    src.fail(in.end_line(), "expected " + std::to_string(total) + " candela values (" +
                                std::to_string(nv) + " vertical x " + std::to_string(nh) +
                                " horizontal), found " + std::to_string(in.left()) +
                                " (the file ends)");
  planes.cd.reserve(static_cast<std::size_t>(total));
  for (long i = 0; i < nh; ++i)
    for (long j = 0; j < nv; ++j) {
      const Token& t = in.take("candela value");
      const std::string at = "the candela value at horizontal " +
                             format_number(planes.h_deg[static_cast<std::size_t>(i)]) +
                             ", vertical " +
                             format_number(planes.v_deg[static_cast<std::size_t>(j)]);
      const double v = parse_number(src, t, at);
      if (v < 0) src.fail(t.line, "expected " + at + " to be >= 0, found " + format_number(v));
      check_intensity(src, t.line, at, v, factor * std::max(max_tilt, 1.0));
      planes.cd.push_back(v * factor);
    }
  if (!in.done())
    src.fail(in.peek().line, "expected " + std::to_string(total) + " candela values (" +
                                 std::to_string(nv) + " vertical x " + std::to_string(nh) +
                                 " horizontal), found more: " + quote_word(in.peek().text));

  check_all_zero(planes, name, p.warnings);
  // Symmetry and expansion.
  SphericalGrid grid;
  glm::dmat3 frame(1.0);
  if (c) {
    Symmetry sym;
    if (!type_c_symmetry(planes.h_deg, sym))
      src.fail(h_line, "horizontal angles " + format_number(planes.h_deg.front()) + ".." +
                           format_number(planes.h_deg.back()) +
                           " fit no symmetry (expected 0; 0..90; 0..180; 90..270; or 0 to "
                           "more than 180, up to 360)");
    p.symmetry = sym;
    check_stored_planes(planes, name, p.warnings);
    check_cut_offs(planes, name, p.warnings);
    std::vector<std::string> notes;
    grid = expand_type_c(planes, sym, &notes);
    for (auto& n : notes) p.warnings.push_back(src.where(h_line) + ": " + n);
  } else {
    p.symmetry = planes.h_deg.size() > 1 && std::abs(planes.h_deg.front()) < 1e-9
                     ? Symmetry::bilateral_c0_c180  // lateral symmetry about the aiming plane
                     : Symmetry::none;
    grid = expand_type_ab(planes, ptype, frame);
  }
  const double tilt0 = p.tilt ? p.tilt->factor_at(0.0) : 1.0;
  if (tilt0 != 1.0)
    for (double& v : grid.cd) v *= tilt0;
  auto table =
      std::make_shared<TabularDistribution>(std::move(grid), Interpolation::bilinear, frame);
  p.table = table;
  p.distribution = table;
  p.counts_vertical = static_cast<int>(nv);
  p.counts_horizontal = static_cast<int>(nh);

  // Lamps and opening.
  LampSet set;
  set.count = static_cast<int>(lamps);
  set.flux_lm = lumens > 0 ? lumens * static_cast<double>(lamps) : 0.0;
  set.power_w = watts;
  if (auto it = p.keywords.find("LAMP"); it != p.keywords.end()) set.type = it->second;
  p.lamp_sets.push_back(set);
  // LM-63: lumens per lamp = -1 means absolute photometry (the candela values are the
  // luminaire's own); otherwise the values are for lamps of that rated flux.
  if (lumens > 0 && lamps > 0) {
    p.lamp_flux_lm = lumens * static_cast<double>(lamps);
    p.flux_convention = "relative photometry (IES: " + std::to_string(lamps) + " x " +
                        format_number(lumens) + " lm rated lamp flux)";
  } else {
    p.flux_convention =
        lumens == -1.0 ? "absolute photometry (IES lumens per lamp = -1)"
        : lumens > 0   ? "absolute photometry (IES: 0 lamps, read as lumens per lamp = -1)"
                       : "absolute photometry (IES lumens per lamp = " + format_number(lumens) +
                           ", read as -1)";
    if (lumens > 0)
      p.warnings.push_back(src.where(lumens_tok.line) + ": 0 lamps of " + format_number(lumens) +
                           " lm give no lamp flux; read as absolute photometry");
    else if (lumens != -1.0)
      p.warnings.push_back(src.where(lumens_tok.line) + ": lumens per lamp " +
                           format_number(lumens) +
                           " is neither -1 nor a rated flux; read as absolute photometry");
  }
  std::string opening_warning;
  p.opening = ies_opening(width * unit, length * unit, height * unit, opening_warning);
  if (!opening_warning.empty()) p.warnings.push_back(name + ": " + opening_warning);
  check_ies_size_signs(ver.year, width * unit, length * unit, height * unit, name, p.warnings);
  return p;
}

}  // namespace luxgrid::photometry
