#include "report/csv.h"

#include <charconv>
#include <cstdio>
#include <string_view>

#include "report/chunked_text.h"
#include "report/number_text_memo.h"
#include "report/piece_buffer.h"

namespace luxgrid::report {

namespace {
// An observers surface: a row per view with the eye, the line of sight, UGR (empty when no
// luminaire is in the view), the background luminance and the illuminance at the eye.
std::string observers_csv(const calc::SurfaceResult& r) {
  std::string out = "observer,x,y,z,dx,dy,dz,UGR,Lb_cd_m2,E_lx,E_indirect_lx\n";
  char line[512];
  size_t k = 0;
  for (size_t o = 0; o < r.observers.size(); ++o) {
    for (const auto& v : r.observers[o].views) {
      char ugr[32] = "";
      if (v.UGR) std::snprintf(ugr, sizeof ugr, "%.6g", *v.UGR);
      const auto& p = r.observers[o].at;
      std::snprintf(line, sizeof line, "%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%s,%.6g,%.6g,%.6g\n", o,
                    p.x, p.y, p.z, v.direction.x, v.direction.y, v.direction.z, ugr, v.Lb_cd_m2,
                    k < r.E.size() ? r.E[k] : 0.0, v.E_indirect_lx);
      out += line;
      ++k;
    }
  }
  return out;
}

// Numbers as printf's "%.6g" writes them (std::to_chars with a precision is specified so),
// without printf's format parsing and locale: a large grid's CSV is a million rows.
struct SixDigits {
  char* operator()(double v, char* first) const {
    return std::to_chars(first, first + NumberTextMemo<SixDigits>::kMaxChars, v,
                         std::chars_format::general, 6)
        .ptr;
  }
};

// Rows [begin, end) of a grid's or points surface's CSV.
void point_rows(const calc::SurfaceResult& r, size_t begin, size_t end, std::string& out) {
  // The last column says what the E columns measure (results.json's "quantity"), so a CSV read on
  // its own cannot pass a cylindrical value off as a planar one. nx, ny, nz are the receiver
  // normal: for a semi-cylindrical surface the direction the half cylinder faces. A point left
  // out of the calculation (outside an L-shaped workplane, inside an obstacle) says active =
  // false and leaves its E cells empty, so a spreadsheet's MIN and AVERAGE over a column skip
  // it, as the statistics do.
  const auto& g = r.grid;
  const std::string quantity = std::string(",") + geometry::to_string(g.quantity);
  const bool daylight = !r.DF.empty();  // DF, SC, ERC, IRC (percent) after the quantity
  constexpr size_t kRowBytes = 8 * 14 + 3 * 13 + 16;  // digits, signs, exponents, separators
  out.reserve(out.size() + (end - begin) * (kRowBytes + quantity.size()));
  // One memo per thread: the chunks of one CSV (and the next CSV) share its coordinates.
  static thread_local NumberTextMemo<SixDigits> memo;
  PieceBuffer row(out);
  char digits[16];
  const auto put_int = [&](int v) {
    row.put(std::string_view(digits, std::to_chars(digits, digits + sizeof digits, v).ptr));
  };
  const auto put = [&](double v) { row.put(memo.text(v)); };
  const int nu = g.nu > 0 ? g.nu : 1;
  for (size_t k = begin; k < end; ++k) {
    const auto& p = g.points[k];
    const auto& n = g.normals[k];
    put_int(static_cast<int>(k % nu));
    row.put(',');
    put_int(static_cast<int>(k / nu));
    for (const double v : {p.x, p.y, p.z, n.x, n.y, n.z}) {
      row.put(',');
      put(v);
    }
    if (g.active.empty() || g.active[k]) {
      row.put(",true");
      for (const double v : {r.E[k], r.E_direct[k], r.E_indirect[k]}) {
        row.put(',');
        put(v);
      }
    } else {
      row.put(",false,,,");
    }
    row.put(quantity);
    if (daylight) {
      for (const double v : {r.DF[k], r.SC[k], r.ERC[k], r.IRC[k]}) {
        row.put(',');
        if (g.active.empty() || g.active[k]) put(v);
      }
    }
    if (!r.E_sun_direct.empty()) {
      for (const double v : {r.E_sun_direct[k], r.E_sun_reflected[k]}) {
        row.put(',');
        if (g.active.empty() || g.active[k]) put(v);
      }
    }
    row.put('\n');
  }
}

// Rows a chunk: about 180 kB of text, formatted in parallel (report/chunked_text.h). Small
// enough that the chunks in flight (four per worker) touch little fresh memory: with 8192 rows
// they held 12 MB, whose first-touch faults cost the 40 000-point panel 5 % of its wall time.
constexpr size_t kRowsPerChunk = 1024;
}  // namespace

std::string surface_csv(const calc::SurfaceResult& r) {
  if (r.grid.kind == geometry::SurfaceGrid::Kind::observers) return observers_csv(r);
  std::string out = std::string(kSurfaceCsvHeader) + (r.DF.empty() ? "" : kDaylightCsvColumns) +
                    (r.E_sun_direct.empty() ? "" : kSunCsvColumns) + "\n";
  point_rows(r, 0, r.grid.points.size(), out);
  return out;
}

void write_surface_csv(std::ostream& out, const calc::SurfaceResult& r) {
  if (r.grid.kind == geometry::SurfaceGrid::Kind::observers) {
    out << observers_csv(r);
    return;
  }
  out << kSurfaceCsvHeader << (r.DF.empty() ? "" : kDaylightCsvColumns)
      << (r.E_sun_direct.empty() ? "" : kSunCsvColumns) << '\n';
  write_chunked(
      r.grid.points.size(), kRowsPerChunk,
      [&](size_t begin, size_t end, std::string& text) { point_rows(r, begin, end, text); },
      [&](std::string_view text) {
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
      });
}

}  // namespace luxgrid::report
