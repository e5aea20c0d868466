#include "project/task_presets.h"

namespace luxgrid::project {

// The rows, copied from the edition each names [EN12464-1] [EN12464-1-2011]. Reference numbers
// and table numbers are those of the 2011 edition's schedule (clause 5), which public copies
// quote; docs/compliance.md says which values were checked against which public copy.
const std::vector<TaskPreset>& task_presets() {
  static const std::vector<TaskPreset> rows = {
      {"office-writing", "Offices: writing, typing, reading, data processing", "EN 12464-1:2021",
       "Table 5.26 Offices", "5.26.2", 500.0, 0.60, 19.0, 80.0, 150.0, 150.0, 100.0},
      {"classroom", "Educational buildings: classrooms, tutorial rooms", "EN 12464-1:2011",
       "Table 5.36 Educational buildings", "5.36.2", 300.0, 0.60, 19.0, 80.0, std::nullopt,
       std::nullopt, std::nullopt},
      {"ward-general", "Health care: wards, general lighting", "EN 12464-1:2011",
       "Table 5.39 Wards, maternity wards", "5.39.1", 100.0, 0.40, 19.0, 80.0, std::nullopt,
       std::nullopt, std::nullopt},
      {"assembly-rough", "Industry: assembly work, rough (e.g. large transformers)",
       "EN 12464-1:2011", "Table 5.5 Electrical and electronic industry", "5.5.5", 300.0, 0.60,
       25.0, 80.0, std::nullopt, std::nullopt, std::nullopt},
      {"assembly-medium", "Industry: assembly work, medium (e.g. switchboards)", "EN 12464-1:2011",
       "Table 5.5 Electrical and electronic industry", "5.5.6", 500.0, 0.60, 22.0, 80.0,
       std::nullopt, std::nullopt, std::nullopt},
      {"assembly-fine", "Industry: assembly work, fine (e.g. telephones)", "EN 12464-1:2011",
       "Table 5.5 Electrical and electronic industry", "5.5.7", 750.0, 0.70, 19.0, 80.0,
       std::nullopt, std::nullopt, std::nullopt},
      {"corridor", "Circulation areas and corridors", "EN 12464-1:2011",
       "Table 5.1 Traffic zones inside buildings", "5.1.1", 100.0, 0.40, 28.0, 40.0, std::nullopt,
       std::nullopt, std::nullopt},
  };
  return rows;
}

const TaskPreset* find_task_preset(const std::string& key) {
  for (const auto& p : task_presets()) {
    if (key == p.key) return &p;
  }
  return nullptr;
}

std::string task_preset_keys() {
  std::string out;
  for (const auto& p : task_presets()) out += (out.empty() ? "" : ", ") + std::string(p.key);
  return out;
}

}  // namespace luxgrid::project
