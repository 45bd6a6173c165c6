#include "json_parser.hpp"

#include <string>

namespace skytrack::io {

Expected<simdjson::dom::element> parse_json_line(std::string_view line, std::size_t capacity) {
  thread_local simdjson::dom::parser parser;
  simdjson::dom::element root;
  const bool padded = capacity >= line.size() + simdjson::SIMDJSON_PADDING;
  const auto error = parser.parse(line.data(), line.size(), !padded).get(root);
  if (error != simdjson::SUCCESS) {
    // After a failure (a failed allocation above all) the parser's state is not to be
    // trusted: the next line gets a new one.
    parser = simdjson::dom::parser{};
    return make_error(std::string("invalid JSON: ") + simdjson::error_message(error));
  }
  return root;
}

}  // namespace skytrack::io
