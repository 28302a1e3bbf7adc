#include "core/term.h"

namespace archgeo {

double TermContext::Number(const std::string& option) const {
  return settings().Number("terms." + term_name() + "." + option);
}

long long TermContext::Integer(const std::string& option) const {
  return settings().Integer("terms." + term_name() + "." + option);
}

bool TermContext::Bool(const std::string& option) const {
  return settings().Bool("terms." + term_name() + "." + option);
}

const std::string& TermContext::String(const std::string& option) const {
  return settings().String("terms." + term_name() + "." + option);
}

}  // namespace archgeo
