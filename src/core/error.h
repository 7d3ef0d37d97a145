#pragma once
// Errors that reach the user: bad files, bad arguments. They carry a ready-to-print message
// (with file:line:col where one applies) so the top level only has to print and exit.
#include <stdexcept>
#include <string>

namespace bz {

class UserError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace bz
