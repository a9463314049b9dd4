#include "drawing_json.h"

namespace dream::view {

void AppendShapes(JsonWriter& json, const std::vector<lcm::DrawnShape>& shapes) {
  constexpr int kMetres = 4;
  json.BeginArray();
  for (const lcm::DrawnShape& shape : shapes) {
    json.BeginArray().Integer(shape.kind).Integer(shape.rgba);
    json.Number(shape.width_m, kMetres).Number(shape.size_m, kMetres).Integer(shape.fill ? 1 : 0);
    json.BeginArray();
    for (const double x : shape.x_m) json.Number(x, kMetres);
    json.EndArray().BeginArray();
    for (const double y : shape.y_m) json.Number(y, kMetres);
    json.EndArray().String(shape.text).EndArray();
  }
  json.EndArray();
}

}  // namespace dream::view
