#include "app/json_text.h"

namespace bz::app {

std::string json_text(const Json& value) {
    return value.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace bz::app
