// Ground-truth lines (CONTRACTS.md §2). Any invalid object rejects the whole line: an
// evaluation against half a truth frame would be silently wrong.
#include <limits>
#include <string>

#include "json_fields.hpp"
#include "json_parser.hpp"

namespace skytrack::io {
namespace {

using namespace detail;

Expected<TruthObject> parse_truth_object(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  TruthObject object;
  auto id = required<std::int64_t>(*obj, path, "id", as_integer);
  if (!id) return unexpected(id.error());
  object.id = *id;
  auto kind = optional_field<std::string_view>(*obj, path, "kind", as_string);
  if (!kind) return unexpected(kind.error());
  if (*kind) {
    const auto parsed = parse_object_kind(**kind);
    if (!parsed) return make_error(join(path, "kind") + ": expected point, group or extended");
    object.kind = *parsed;
  }
  const auto position = field(*obj, "position");
  if (!position) return make_error(join(path, "position") + ": missing required field");
  auto p = as_vector23(*position, join(path, "position"), &object.dims);
  if (!p) return unexpected(p.error());
  object.position = *p;
  if (const auto velocity = field(*obj, "velocity")) {
    int dims = 0;
    auto v = as_vector23(*velocity, join(path, "velocity"), &dims);
    if (!v) return unexpected(v.error());
    if (dims != object.dims)
      return make_error(join(path, "velocity") + ": dims differ from position");
    object.velocity = *v;
  }
  auto extent = optional_field<Eigen::Matrix2d>(*obj, path, "extent", as_extent);
  if (!extent) return unexpected(extent.error());
  object.extent = *extent;
  auto members = optional_field<std::int64_t>(*obj, path, "members", as_integer);
  if (!members) return unexpected(members.error());
  if (*members) {
    if (**members < 0) return make_error(join(path, "members") + ": negative");
    if (**members > std::numeric_limits<int>::max()) {
      return make_error(join(path, "members") + ": " + std::to_string(**members) +
                        " is beyond " + std::to_string(std::numeric_limits<int>::max()));
    }
    object.members = static_cast<int>(**members);
  }
  return object;
}

}  // namespace

Expected<TruthFrame> parse_truth_frame(const element& root) {
  auto obj = as_object(root, "line");
  if (!obj) return unexpected(obj.error());
  TruthFrame frame;
  auto time = required<double>(*obj, "", "time", as_finite);
  if (!time) return unexpected(time.error());
  frame.time = *time;
  auto objects = required<simdjson::dom::array>(*obj, "", "objects", as_array);
  if (!objects) return unexpected(objects.error());
  frame.objects.reserve(objects->size());
  std::size_t index = 0;
  for (element item : *objects) {
    auto object = parse_truth_object(item, indexed("objects", index++));
    if (!object) return unexpected(object.error());
    frame.objects.push_back(std::move(*object));
  }
  return frame;
}

Expected<TruthFrame> parse_truth_frame(std::string_view line) {
  auto root = parse_json_line(line);
  if (!root) return unexpected(root.error());
  return parse_truth_frame(*root);
}

}  // namespace skytrack::io
