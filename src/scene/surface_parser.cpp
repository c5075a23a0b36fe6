#include "scene/surface_parser.h"

#include "scene/block_reader.h"
#include "scene/keywords.h"
#include "scene/number_text.h"
#include "scene/value_reader.h"
#include "trace/bsdf.h"

namespace prt {
namespace {

const Material& lookUp(const TokenStream& in, const Token& name, const MaterialTable& materials) {
  const auto found = materials.find(name.text);
  if (found != materials.end()) return found->second.material;
  if (materials.empty()) {
    in.fail(name, "unknown material " + describe(name) +
                      "; no materials are defined yet (define one first with material NAME "
                      "{ ... })");
  }
  std::vector<std::string_view> names;
  for (const auto& entry : materials) names.push_back(entry.first);
  const std::string message =
      "unknown material " + describe(name) + didYouMean(name.text, names) +
      "; defined materials: " + joinNames(names) + " (a material must be defined before its use)";
  in.fail(name, message);
}

// Overrides fields of `material` with those given in the block that comes next.
void readSurfaceBlock(TokenStream& in, const Token& keyword, const std::string& title,
                      Material& material) {
  BlockReader block(in, keyword, title,
                    {"color", "ambient", "diffuse", "specular", "phong", "reflect", "transmit",
                     "ior", "gloss", "translucency", "metallic", "emission", "base_color",
                     "roughness", "transmission", "pbr_ior", "specular_level", "coverage",
                     "attenuation_color", "attenuation_distance", "thin_walled", "specular_weight",
                     "specular_color", "clearcoat", "clearcoat_roughness"});
  const Range weight = Range::closed(0, 1);
  while (const Token* param = block.next()) {
    const std::string& name = param->text;
    if (name == "color" || name == "base_color") {
      material.color = readColor(in, name);
    } else if (name == "roughness") {
      material.pbr.roughness = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "transmission") {
      material.pbr.transmission = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "pbr_ior") {
      material.pbr.ior = readNumber(in, name, Range::closed(1, 10));
    } else if (name == "specular_level") {
      // Above 12.5 the reflectance at normal incidence would pass 1.
      material.pbr.specularLevel = readNumber(in, name, Range::closed(0, kMaxSpecularLevel));
      material.pbr.given = true;
    } else if (name == "coverage") {
      material.pbr.coverage = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "attenuation_color") {
      material.pbr.attenuationColor = readVector(in, name, weight);
      material.pbr.given = true;
    } else if (name == "attenuation_distance") {
      material.pbr.attenuationDistance = readNumber(in, name, Range::above(0));
      material.pbr.given = true;
    } else if (name == "thin_walled") {  // a flag: no value
      material.pbr.thinWalled = true;
      material.pbr.given = true;
    } else if (name == "specular_weight") {
      material.pbr.specularWeight = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "specular_color") {
      material.pbr.specularColor = readColor(in, name);
      material.pbr.given = true;
    } else if (name == "clearcoat") {
      material.pbr.clearcoat = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "clearcoat_roughness") {
      material.pbr.clearcoatRoughness = readNumber(in, name, weight);
      material.pbr.given = true;
    } else if (name == "ambient") {
      material.ambient = readNumber(in, name, weight);
    } else if (name == "diffuse") {
      material.diffuse = readNumber(in, name, weight);
    } else if (name == "specular") {
      material.specular = readNumber(in, name, weight);
    } else if (name == "phong") {
      material.phongExponent = readNumber(in, name, Range::atLeast(1));
    } else if (name == "reflect") {
      material.reflectivity = readNumber(in, name, weight);
    } else if (name == "transmit") {
      material.transmissivity = readNumber(in, name, weight);
    } else if (name == "ior") {
      // Above 10 no real material exists; such a value is almost surely a typo.
      material.ior = readNumber(in, name, Range::closed(1, 10));
      material.pbr.ior = material.ior;
    } else if (name == "gloss") {
      material.glossDegrees = readNumber(in, name, Range::closedOpen(0, 90));
    } else if (name == "metallic") {
      material.metallic = readNumber(in, name, weight);
    } else if (name == "emission") {
      material.emission = readColor(in, name);
    } else {
      material.translucencyDegrees = readNumber(in, name, Range::closedOpen(0, 90));
    }
  }
  // A surface that sends on more light than reaches it makes every bounce multiply the
  // light: the image grows without bound with max_depth, and so does the cost, the path
  // weights never falling below the shader's cut-off (its bound needs reflect + transmit <= 1).
  if (material.reflectivity + material.transmissivity > 1 &&
      (block.has("reflect") || block.has("transmit"))) {
    const bool reflectLast =
        block.has("reflect") &&
        (!block.has("transmit") || block.valueIndex("reflect") > block.valueIndex("transmit"));
    in.fail(block.valueToken(reflectLast ? "reflect" : "transmit"),
            "'reflect' + 'transmit' must be at most 1 (a surface cannot send on more light than "
            "reaches it), found " + formatDouble(material.reflectivity) + " + " +
                formatDouble(material.transmissivity));
  }
}

}  // namespace

Material readSurface(TokenStream& in, const Token& keyword, const std::string& title,
                     const MaterialTable& materials) {
  Material material;
  const Token& first = in.peek();
  if (first.kind == TokenKind::Word) {
    material = lookUp(in, in.next(), materials);
    if (in.peek().kind != TokenKind::LeftBrace) return material;
  } else if (first.kind != TokenKind::LeftBrace) {
    in.fail(first, "expected a material name or a '{ ... }' block of surface parameters after " +
                       describe(keyword) + ", found " + describe(first));
  }
  readSurfaceBlock(in, keyword, title, material);
  return material;
}

}  // namespace prt
