#include "OgreMaterialScript.h"

#include <lacrima/exporters/RigExport.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <set>

namespace lacrima::exporters {
namespace {

// A cornea with the loader's default, nearly matt specular would be invisible: these minimums
// give the small sharp highlight that makes an eye look wet.
constexpr float kCorneaSpecular = 0.9f;
constexpr float kCorneaShininess = 96.0f;

// Shortest text that reads back as the same float, without exponent (OGRE parses both, but
// "0.8" is what people expect to read in a script).
std::string number(float value) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  return std::string(buffer, result.ptr);
}

std::string numbers(std::initializer_list<float> values) {
  std::string text;
  for (float v : values) {
    if (!text.empty()) text += ' ';
    text += number(v);
  }
  return text;
}

// Script names and file names are written in double quotes, which the script lexer does not
// escape; a quote or line break in a name would end the token early.
std::string scriptSafe(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '"' || c == '\n' || c == '\r'; }, '_');
  return text;
}

// `stem` + `extension` if not in `taken`, else the first free stem + "_2", "_3", ... + extension;
// the result is marked as taken.
std::string takeUnique(std::set<std::string>& taken, const std::string& stem,
                       const std::string& extension = {}) {
  std::string candidate = stem + extension;
  for (int k = 2; taken.contains(candidate); ++k)
    candidate = stem + "_" + std::to_string(k) + extension;
  taken.insert(candidate);
  return candidate;
}

void appendPass(std::string& text, const HeadMaterial& m, bool cornea, const std::string& texture) {
  const Eigen::Vector4f& d = m.diffuse;
  text += "    pass\n    {\n";
  if (cornea) {
    const Eigen::Vector3f s = m.specular.cwiseMax(kCorneaSpecular);
    text += "      ambient 0 0 0\n";
    text += "      diffuse 0 0 0 1\n";
    text += "      specular " +
            numbers({s.x(), s.y(), s.z(), std::max(m.shininess, kCorneaShininess)}) + "\n";
    // Additive: black diffuse adds nothing, the highlight brightens the eyeball below.
    text += "      scene_blend add\n";
    text += "      depth_write off\n";
  } else {
    const Eigen::Vector3f& s = m.specular;
    text += "      ambient " + numbers({d.x(), d.y(), d.z()}) + "\n";
    text += "      diffuse " + numbers({d.x(), d.y(), d.z(), d.w()}) + "\n";
    text += "      specular " + numbers({s.x(), s.y(), s.z(), m.shininess}) + "\n";
    if (m.transparent) {
      // Without depth_write off, a lash drawn first would hide the lashes behind it.
      text += "      scene_blend alpha_blend\n";
      text += "      depth_write off\n";
    }
    if (!texture.empty())
      text += "      texture_unit\n      {\n        texture \"" + texture + "\"\n      }\n";
  }
  text += "    }\n";
}

}  // namespace

OgreMaterialScript makeOgreMaterialScript(const HeadMesh& head, const std::string& prefix) {
  OgreMaterialScript script;
  std::set<std::string> takenNames, takenFiles;
  std::map<std::string, std::string> fileOfSource;
  for (std::size_t i = 0; i < head.materials.size(); ++i) {
    const HeadMaterial& m = head.materials[i];
    const bool cornea = isCorneaMaterial(head, static_cast<int>(i));
    const std::string base = m.name.empty() ? "material" + std::to_string(i) : m.name;
    const std::string name = takeUnique(takenNames, scriptSafe(prefix + "/" + base));
    script.names.push_back(name);

    std::string texture;
    if (!m.diffuseTexture.empty() && !cornea) {
      auto [it, isNew] = fileOfSource.try_emplace(m.diffuseTexture);
      if (isNew) {
        const std::filesystem::path source(m.diffuseTexture);
        it->second = takeUnique(takenFiles, scriptSafe(source.stem().string()),
                                scriptSafe(source.extension().string()));
        script.textures.push_back({m.diffuseTexture, it->second});
      }
      texture = it->second;
    }
    script.text += "material \"" + name + "\"\n{\n  technique\n  {\n";
    appendPass(script.text, m, cornea, texture);
    script.text += "  }\n}\n\n";
  }
  return script;
}

}  // namespace lacrima::exporters
