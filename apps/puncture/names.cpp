#include "names.hpp"

namespace puncture::cli {

std::string configuration_token(Configuration configuration) { return to_token(configuration); }

std::string material_token(const MaterialLaw& law) { return law_name(law); }

}  // namespace puncture::cli
