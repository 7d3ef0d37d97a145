#pragma once
// A minimal JSON writer for benchmark reports: objects, arrays, strings, numbers, booleans,
// two-space indentation. Non-finite numbers are written as null (JSON has no NaN).
#include <string>
#include <string_view>
#include <vector>

namespace bz::app {

class JsonWriter {
  public:
    JsonWriter& begin_object();
    JsonWriter& end_object();
    JsonWriter& begin_array();
    JsonWriter& end_array();
    JsonWriter& key(std::string_view k);
    JsonWriter& value(std::string_view s);
    JsonWriter& value(const char* s) { return value(std::string_view(s)); }
    JsonWriter& value(double v);
    JsonWriter& value(int v) { return value(static_cast<double>(v)); }
    JsonWriter& value(std::size_t v) { return value(static_cast<double>(v)); }
    JsonWriter& value(bool v);
    template <class T>
    JsonWriter& field(std::string_view k, const T& v) {
        key(k);
        return value(v);
    }
    const std::string& str() const { return out_; }

  private:
    void before_value();
    void newline();
    std::string out_;
    std::vector<bool> first_;  // per open container: nothing written in it yet
    bool after_key_ = false;
};

std::string json_escape(std::string_view s);

}  // namespace bz::app
