// EULUMDAT (.ldt) reader.
//
// A primer on the format (one field a line; Ashdown's English translation of the 1990 spec):
//    1 company            2 Ityp (type indicator)     3 Isym (symmetry, 0..4)
//    4 Mc (C planes)      5 Dc (C spacing; 0 = list irregular)
//    6 Ng (gamma values)  7 Dg (gamma spacing; 0 = irregular)
//    8 report  9 luminaire name  10 luminaire number  11 file name  12 date/user
//   13-15 luminaire length/diameter, width (0 = circular), height [mm]
//   16-17 luminous area length/diameter, width (0 = circular) [mm]
//   18-21 luminous area height in the C0, C90, C180, C270 planes [mm]
//   22 DFF [%]   23 LORL [%]   24 conversion factor for intensities   25 tilt during measurement
//   26 n lamp sets, then per set: number of lamps (< 0: absolute photometry), type, total flux
//      [lm], colour, colour rendering, wattage [W]
//   then 10 direct ratios (room indices 0.6 .. 5), Mc C angles, Ng gamma angles, and the
//   intensities [cd/klm] of the stored planes, Ng values each:
//     Isym 0: all Mc planes   1: one plane   2: C0..C180   3: C90..C270   4: C0..C90
//   (Isym 3 is stored from C90 upwards, as QLumEdit, DIALux and the road-lighting convention
//   of a street side at C90 read it.)
//
// Absolute candela = value x (flux of lamp set 1) / 1000 x conversion factor.
// Policy: empty text fields, empty direct ratios and decimal commas (with a warning) are
// accepted; every number the intensities depend on must be present and valid.
#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "photometry/file_warnings.h"
#include "photometry/opening.h"
#include "photometry/readers.h"
#include "photometry/source_text.h"
#include "photometry/symmetry.h"
#include "photometry/table_warnings.h"
#include "photometry/tabular_distribution.h"
#include "util/error.h"

namespace luxgrid::photometry {

namespace {

class LdtLines {
 public:
  LdtLines(const SourceText& src, Photometry& p) : src_(src), p_(p) {}

  std::string text(int n) const { return clean_text(src_.line(n)); }

  bool try_number(int n, double& v) {
    const std::string_view t = trim(src_.line(n));
    if (try_parse_number(t, v)) return true;
    // A decimal comma ("84,42"): read it, and say so once.
    if (t.find(',') != std::string_view::npos && t.find('.') == std::string_view::npos &&
        std::count(t.begin(), t.end(), ',') == 1) {
      std::string s(t);
      std::replace(s.begin(), s.end(), ',', '.');
      if (try_parse_number(s, v)) {
        if (!comma_warned_) {
          p_.warnings.push_back(src_.where(n) + ": decimal comma read as a decimal point");
          comma_warned_ = true;
        }
        return true;
      }
    }
    return false;
  }
  double number(int n, const std::string& what) {
    if (n > src_.line_count())
      src_.fail(src_.line_count(), "expected " + what + " on line " + std::to_string(n) +
                                       ", found the end of the file");
    double v;
    if (!try_number(n, v)) {
      const std::string_view t = trim(src_.line(n));
      src_.fail(n, "expected a number for " + what + ", found " + describe_line(t));
    }
    return v;
  }
  // Optional numbers (dimensions, direct ratios): an empty line reads as 0.
  double optional_number(int n, const std::string& what) {
    if (trim(src_.line(n)).empty()) return 0.0;
    return number(n, what);
  }
  long count(int n, const std::string& what, long lo, long hi) {
    const double v = number(n, what);
    if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi))
      src_.fail(n, "expected " + what + " to be a whole number from " + std::to_string(lo) +
                       " to " + std::to_string(hi) + ", found " + describe_line(src_.line(n)));
    return static_cast<long>(v);
  }

 private:
  const SourceText& src_;
  Photometry& p_;
  bool comma_warned_ = false;
};

// Numbers from `first_line` on, one or more a line, with decimal commas tolerated.
class LdtValues {
 public:
  LdtValues(const SourceText& src, int first_line) : src_(src) {
    tokens_ = src.tokens_from(first_line);  // commas split tokens; decimal commas are rare
    // (none in ~100 real files); a line holding exactly one "a,b" token reads as a decimal.
    std::vector<Token> merged;
    for (std::size_t k = 0; k < tokens_.size(); ++k) {
      const std::string_view line = trim(src.line(tokens_[k].line));
      if (k + 1 < tokens_.size() && tokens_[k + 1].line == tokens_[k].line &&
          std::count(line.begin(), line.end(), ',') == 1 &&
          line.find_first_of(" \t") == std::string_view::npos &&
          line.find('.') == std::string_view::npos) {
        owned_.push_back(std::string(tokens_[k].text) + "." + std::string(tokens_[k + 1].text));
        merged.push_back({{}, tokens_[k].line});
        merged.back().text = owned_.back();
        ++k;
        continue;
      }
      merged.push_back(tokens_[k]);
    }
    tokens_ = std::move(merged);
  }
  bool done() const { return next_ >= tokens_.size(); }
  std::size_t left() const { return tokens_.size() - next_; }
  int end_line() const { return tokens_.empty() ? src_.line_count() : tokens_.back().line; }
  const Token& peek() const { return tokens_[next_]; }
  double take(const std::string& what) {
    if (done()) src_.fail(end_line(), "expected " + what + ", found the end of the file");
    return parse_number(src_, tokens_[next_++], what);
  }
  int line() const { return next_ > 0 ? tokens_[next_ - 1].line : 0; }

 private:
  const SourceText& src_;
  std::vector<Token> tokens_;
  std::deque<std::string> owned_;
  std::size_t next_ = 0;
};

std::vector<double> read_angles(const SourceText& src, LdtValues& in, long n, const char* what,
                                double lo, double hi_exclusive_or_inclusive, bool inclusive) {
  std::vector<double> a;
  for (long k = 0; k < n; ++k) {
    if (in.done())
      src.fail(in.end_line(), "expected " + std::to_string(n) + " " + what + " angles, found " +
                                  std::to_string(k) + " (the file ends)");
    const double v = in.take(std::string(what) + " angle " + std::to_string(k + 1));
    if (!a.empty() && !(v > a.back()))
      src.fail(in.line(), std::string(what) + " angles must increase: " + format_number(v) +
                              " follows " + format_number(a.back()));
    const bool above =
        inclusive ? v > hi_exclusive_or_inclusive + 1e-9 : v >= hi_exclusive_or_inclusive - 1e-9;
    if (v < lo - 1e-9 || above)
      src.fail(in.line(), "expected " + std::string(what) + " angles from " + format_number(lo) +
                              (inclusive ? " to " : " to below ") +
                              format_number(hi_exclusive_or_inclusive) + ", found " +
                              format_number(v));
    a.push_back(v);
  }
  return a;
}

bool same(double a, double b) { return std::abs(a - b) < 1e-6; }

}  // namespace

Photometry read_eulumdat(std::string_view bytes, const std::string& name) {
  const SourceText src(bytes, name);
  Photometry p;
  p.source = name;
  p.format = "EULUMDAT";
  p.version = "EULUMDAT";
  if (src.line_count() == 0 || trim(bytes).empty()) src.fail(0, "file is empty");
  LdtLines L(src, p);

  auto keyword = [&](const char* key, int n) {
    const std::string t = L.text(n);
    if (!t.empty()) p.keywords[key] = t;
  };
  keyword("COMPANY", 1);
  const long ityp = L.count(2, "the type indicator Ityp", 0, 3);
  const long isym = L.count(3, "the symmetry indicator Isym", 0, 4);
  const long mc = L.count(4, "the number of C planes Mc", 1, kMaxAngles);
  const double dc = L.number(5, "the C plane distance Dc");
  const long ng = L.count(6, "the number of gamma angles Ng", 2, kMaxAngles);
  const double dg = L.number(7, "the gamma distance Dg");
  keyword("REPORT", 8);
  keyword("LUMINAIRE", 9);
  keyword("LUMCAT", 10);
  keyword("FILENAME", 11);
  keyword("DATE", 12);
  const double lum_length = L.optional_number(13, "the luminaire length");
  const double lum_width = L.optional_number(14, "the luminaire width");
  const double lum_height = L.optional_number(15, "the luminaire height");
  const double area_length = L.optional_number(16, "the luminous area length");
  check_opening_size(src, 16, "the luminous area length", area_length / 1000.0);
  check_eulumdat_size_sign(area_length, "the luminous area length", src.where(16), p.warnings);
  const double area_width = L.optional_number(17, "the luminous area width");
  check_opening_size(src, 17, "the luminous area width", area_width / 1000.0);
  check_eulumdat_size_sign(area_width, "the luminous area width", src.where(17), p.warnings);
  double area_height = 0.0;
  for (int n = 18; n <= 21; ++n) {
    const double h = L.optional_number(n, "a luminous area height");
    check_opening_size(src, n, "a luminous area height", h / 1000.0);
    check_eulumdat_size_sign(h, "a luminous area height", src.where(n), p.warnings);
    area_height = std::max(area_height, h);
  }
  const double dff = L.number(22, "the downward flux fraction DFF");
  const double lor = L.number(23, "the light output ratio LORL");
  const double conv = L.number(24, "the conversion factor for luminous intensities");
  if (!(conv > 0)) src.fail(24, "expected a conversion factor > 0, found " + format_number(conv));
  const double tilt = L.optional_number(25, "the tilt of the luminaire during measurement");
  const long nsets = L.count(26, "the number of lamp sets", 1, 1000);
  for (long s = 0; s < nsets; ++s) {
    const int base = 27 + static_cast<int>(s) * 6;
    LampSet set;
    set.count = static_cast<int>(
        L.count(base, "the number of lamps of set " + std::to_string(s + 1), -1000000, 1000000));
    set.type = L.text(base + 1);
    set.flux_lm = L.number(base + 2, "the total lamp flux of set " + std::to_string(s + 1));
    check_lamp_flux(src, base + 2, "the total lamp flux of set " + std::to_string(s + 1),
                    set.flux_lm);
    set.colour = L.text(base + 3);
    set.cri = L.text(base + 4);
    set.power_w = L.optional_number(base + 5, "the wattage of set " + std::to_string(s + 1));
    p.lamp_sets.push_back(set);
  }
  const int dr_line = 27 + static_cast<int>(nsets) * 6;
  for (int k = 0; k < 10; ++k) L.optional_number(dr_line + k, "a direct ratio");
  const int angles_line = dr_line + 10;

  std::string sym_note;
  if (mc * ng > kMaxValues)
    src.fail(6, "expected at most " + std::to_string(kMaxValues) +
                    " intensities, the header claims " + std::to_string(mc) + " x " +
                    std::to_string(ng));
  if ((isym == 2 || isym == 3) && mc % 2 != 0)
    src.fail(4, "expected an even number of C planes for Isym " + std::to_string(isym) +
                    ", found Mc = " + std::to_string(mc));
  if (isym == 4 && mc % 4 != 0)
    src.fail(4, "expected a multiple of 4 C planes for Isym 4, found Mc = " + std::to_string(mc));

  LdtValues in(src, angles_line);
  const int c_line = in.done() ? src.line_count() : in.peek().line;
  const std::vector<double> c_all = read_angles(src, in, mc, "C", 0.0, 360.0, false);
  const int g_line = in.done() ? src.line_count() : in.peek().line;
  StoredPlanes planes;
  planes.v_deg = read_angles(src, in, ng, "gamma", 0.0, 180.0, true);

  Symmetry sym = Symmetry::none;
  std::size_t first = 0, stored = static_cast<std::size_t>(mc);
  auto range = [&](double a, double b) { return format_number(a) + ".." + format_number(b); };
  switch (isym) {
    case 0:
      if (mc == 1) {
        sym = Symmetry::rotational;
        p.warnings.push_back(src.where(3) +
                             ": Isym 0 with a single C plane; read as rotationally symmetric");
      }
      stored = static_cast<std::size_t>(mc);
      break;
    case 1:
      sym = Symmetry::rotational;
      stored = 1;
      break;
    case 2:
      sym = Symmetry::bilateral_c0_c180;
      stored = static_cast<std::size_t>(mc / 2 + 1);
      break;
    case 3: {
      sym = Symmetry::bilateral_c90_c270;
      stored = static_cast<std::size_t>(mc / 2 + 1);
      auto it = std::find_if(c_all.begin(), c_all.end(), [](double c) { return same(c, 90.0); });
      if (it == c_all.end())
        src.fail(c_line,
                 "expected a C90 plane among the C angles for Isym 3 (data stored C90..C270)");
      first = static_cast<std::size_t>(it - c_all.begin());
      break;
    }
    case 4:
      sym = Symmetry::quadrant;
      stored = static_cast<std::size_t>(mc / 4 + 1);
      break;
  }
  if (isym == 1) {
    planes.h_deg = {0.0};
  } else {
    if (first + stored > c_all.size())
      src.fail(c_line, "expected " + std::to_string(stored) + " C planes from C" +
                           format_number(c_all[first]) + ", the list has only " +
                           std::to_string(c_all.size() - first));
    planes.h_deg.assign(c_all.begin() + static_cast<std::ptrdiff_t>(first),
                        c_all.begin() + static_cast<std::ptrdiff_t>(first + stored));
    const double a = planes.h_deg.front(), b = planes.h_deg.back();
    const char* expect = isym == 2   ? "0..180"
                         : isym == 3 ? "90..270"
                         : isym == 4 ? "0..90"
                                     : nullptr;
    const bool ok = isym == 0 || (isym == 2 && same(a, 0) && same(b, 180)) ||
                    (isym == 3 && same(a, 90) && same(b, 270)) ||
                    (isym == 4 && same(a, 0) && same(b, 90));
    if (!ok)
      src.fail(c_line, "expected the stored C planes to span " + std::string(expect) +
                           " for Isym " + std::to_string(isym) + ", found " + range(a, b));
  }
  (void)g_line;

  if (p.lamp_sets.empty() || !(p.lamp_sets.front().flux_lm > 0))
    src.fail(29, "expected a total lamp flux > 0 for lamp set 1, found " +
                     format_number(p.lamp_sets.empty() ? 0.0 : p.lamp_sets.front().flux_lm));
  const double flux1 = p.lamp_sets.front().flux_lm;
  const double factor = flux1 / 1000.0 * conv;
  if (!(factor <= kMaxIntensity_cd))
    src.fail(24, "expected the lamp flux / 1000 x the conversion factor to be at most " +
                     format_number(kMaxIntensity_cd) + ", found " + format_number(factor));
  p.candela_multiplier = factor;
  const std::size_t total = planes.h_deg.size() * static_cast<std::size_t>(ng);
  if (in.left() < total)
    src.fail(in.end_line(), "expected " + std::to_string(total) + " intensities (" +
                                std::to_string(planes.h_deg.size()) + " C planes x " +
                                std::to_string(ng) + " gamma), found " + std::to_string(in.left()) +
                                " (the file ends)");
  planes.cd.reserve(total);
  for (std::size_t i = 0; i < planes.h_deg.size(); ++i)
    for (long j = 0; j < ng; ++j) {
      const std::string at = "the intensity at C" + format_number(planes.h_deg[i]) + ", gamma " +
                             format_number(planes.v_deg[static_cast<std::size_t>(j)]);
      const double v = in.take(at);
      if (v < 0) src.fail(in.line(), "expected " + at + " to be >= 0, found " + format_number(v));
      check_intensity(src, in.line(), at, v, factor);
      planes.cd.push_back(v * factor);
    }
  if (!in.done())
    p.warnings.push_back(src.where(in.peek().line) + ": " + std::to_string(in.left()) +
                         " values after the last expected intensity ignored");

  p.symmetry = sym;
  p.photometric_type = PhotometricType::C;
  check_stored_planes(planes, name, p.warnings);
  check_cut_offs(planes, name, p.warnings);
  check_all_zero(planes, name, p.warnings);
  std::vector<std::string> notes;
  auto table = std::make_shared<TabularDistribution>(expand_type_c(planes, sym, &notes));
  for (auto& n : notes) p.warnings.push_back(name + ": " + n);
  p.table = table;
  p.distribution = table;
  p.counts_vertical = static_cast<int>(ng);
  p.counts_horizontal = static_cast<int>(planes.h_deg.size());

  p.stated_dff = dff / 100.0;
  p.stated_lor = lor / 100.0;
  // EULUMDAT: a negative lamp count means absolute photometry (set 1's flux is then the
  // luminaire's own, and the cd/klm values are scaled by it all the same).
  const int count1 = p.lamp_sets.front().count;
  if (count1 >= 0) {
    p.lamp_flux_lm = flux1;
    p.flux_convention = "relative photometry (EULUMDAT: " + std::to_string(count1) +
                        (count1 == 1 ? " lamp, " : " lamps, ") + format_number(flux1) +
                        " lm rated lamp flux)";
  } else {
    p.flux_convention = "absolute photometry (EULUMDAT lamp count " + std::to_string(count1) +
                        " < 0; " + format_number(flux1) + " lm is the luminaire flux)";
  }
  p.opening = eulumdat_opening(area_length / 1000.0, area_width / 1000.0, area_height / 1000.0);
  p.keywords["_ITYP"] = std::to_string(ityp);
  p.keywords["_ISYM"] = std::to_string(isym);
  p.keywords["_DC"] = format_number(dc);
  p.keywords["_DG"] = format_number(dg);
  p.keywords["_LUMINAIRE_SIZE_MM"] = format_number(lum_length) + " x " + format_number(lum_width) +
                                     " x " + format_number(lum_height);
  if (tilt != 0) p.keywords["_TILT_DURING_MEASUREMENT"] = format_number(tilt);
  return p;
}

}  // namespace luxgrid::photometry
