#pragma once
// Walks a text one line at a time, without the line end ("\n" or "\r\n"), counting lines from
// 1 so a parser can report file:line.
#include <string_view>

namespace bz {

class LineReader {
  public:
    explicit LineReader(std::string_view text) : text_(text) {}
    // Stores the next line in `line`; false once the text is used up.
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++number_;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        return true;
    }
    int line_number() const { return number_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int number_ = 0;
};

}  // namespace bz
