#include "common/errors.hpp"

namespace rbcsim {

InputError::InputError(const std::string& source, const std::string& problem)
    : std::runtime_error(source + ": " + problem) {}

}  // namespace rbcsim
