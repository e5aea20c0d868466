#pragma once
// Task presets: the rows of EN 12464-1's schedule of lighting requirements a project can name
// instead of typing the numbers ("requirements": {"preset": "office-writing"}). Each row cites the
// edition, table and reference number it was copied from [EN12464-1]; docs/compliance.md lists
// them with what each was checked against.
#include <optional>
#include <string>
#include <vector>

namespace luxgrid::project {

struct TaskPreset {
  const char* key;              // what a project writes: "office-writing"
  const char* area;             // the standard's wording of the task or activity
  const char* edition;          // "EN 12464-1:2021"
  const char* table;            // "Table 5.26 Offices"
  const char* reference;        // the standard's reference number, "5.26.2"
  double Em_lx;                 // maintained illuminance on the task area (the "required" column)
  double U0;                    // Emin / Em on the task area
  double UGR_L;                 // the limit of the unified glare rating
  double Ra;                    // the minimum colour rendering index
  std::optional<double> Ez_lx;  // maintained cylindrical illuminance of the activity area
  std::optional<double> Em_wall_lx;     // maintained illuminance on the walls (U0 >= 0.10)
  std::optional<double> Em_ceiling_lx;  // maintained illuminance on the ceiling (U0 >= 0.10)
};

// Every preset, in the order docs/compliance.md lists them.
const std::vector<TaskPreset>& task_presets();

// The preset named `key`, or null.
const TaskPreset* find_task_preset(const std::string& key);

// "office-writing, classroom, ..." for messages.
std::string task_preset_keys();

// The uniformity EN 12464-1 asks of walls and ceilings whatever their illuminance.
inline constexpr double kWallCeilingU0 = 0.10;

// The general floor under every room's walls and ceiling where a row gives none of its own
// (EN 12464-1:2021 clause 5.2.4): walls Em >= 50 lx, ceilings Em >= 30 lx, both U0 >= 0.10.
// A project asks for it with "requirements": {"preset": "walls-and-ceilings"} on room_surfaces.
inline constexpr const char* kWallsAndCeilingsPreset = "walls-and-ceilings";
inline constexpr double kMinWall_lx = 50.0;
inline constexpr double kMinCeiling_lx = 30.0;

}  // namespace luxgrid::project
