#include "names.hpp"

namespace puncture::cli {

std::string configuration_token(Configuration configuration) {
  switch (configuration) {
    case Configuration::Unloaded:
      return "unloaded";
    case Configuration::Stick:
      return "stick";
    case Configuration::SlipWithoutPartTwo:
      return "slip_without_part_two";
    case Configuration::SlipWithPartTwo:
      return "slip_with_part_two";
  }
  return "unknown";
}

std::string material_token(const MaterialLaw& law) { return law_name(law); }

}  // namespace puncture::cli
