#include <lacrima/editing/HeadSetupRoles.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace lacrima::editing {
namespace {

constexpr std::array<std::string_view, kPartRoles.size()> kRoleNames{
    "skin",        "eye_left", "eye_right", "cornea_left", "cornea_right", "teeth_upper",
    "teeth_lower", "tongue",   "attached",  "rigid",       "ignored"};

// A name split into lower-case words: at separators, at a lower-to-upper case change (EyeL ->
// eye, l) and between letters and digits, so that "M_IrisLeft" is {m, iris, left}.
struct Words {
  std::vector<std::string> tokens;
  std::string joined;  // the tokens run together, for keywords inside words (eyelash)

  explicit Words(std::string_view a, std::string_view b) {
    for (std::string_view name : {a, b}) {
      std::string current;
      char previous = 0;
      for (const char c : name) {
        const auto u = static_cast<unsigned char>(c);
        const bool alnum = std::isalnum(u) != 0;
        const bool boundary =
            !alnum || (std::isupper(u) && std::islower(static_cast<unsigned char>(previous))) ||
            (std::isdigit(u) != 0) != (std::isdigit(static_cast<unsigned char>(previous)) != 0);
        if (boundary && !current.empty()) {
          tokens.push_back(current);
          current.clear();
        }
        if (alnum) current += static_cast<char>(std::tolower(u));
        previous = alnum ? c : 0;
      }
      if (!current.empty()) tokens.push_back(current);
      tokens.emplace_back();  // keeps the two names' words apart in `joined`
    }
    for (const std::string& t : tokens) joined += t.empty() ? std::string(" ") : t;
  }

  bool contains(std::initializer_list<std::string_view> keys) const {
    return std::any_of(keys.begin(), keys.end(),
                       [&](std::string_view k) { return joined.find(k) != std::string::npos; });
  }
  bool hasToken(std::initializer_list<std::string_view> keys) const {
    return std::any_of(tokens.begin(), tokens.end(), [&](const std::string& t) {
      return std::find(keys.begin(), keys.end(), t) != keys.end();
    });
  }
  HeadSide side() const {
    const bool left = contains({"left"}) || hasToken({"l", "lt", "lf"});
    const bool right = contains({"right"}) || hasToken({"r", "rt"});
    if (left == right) return HeadSide::Unknown;
    return left ? HeadSide::Left : HeadSide::Right;
  }
};

bool isEye(const Words& w) { return w.contains({"eye", "iris", "sclera", "pupil"}); }
bool isCornea(const Words& w) { return w.contains({"cornea"}); }
bool isTeeth(const Words& w) { return w.contains({"teeth", "tooth", "gum"}); }
bool namesTeethHalf(const Words& w) {
  return w.contains({"upper", "top", "lower", "bottom", "jaw"});
}

Eigen::Vector3f centre(const HeadMesh& mesh, const HeadSubmesh& part) {
  if (part.vertexCount == 0) return Eigen::Vector3f::Zero();
  return mesh.positions.middleCols(part.firstVertex, part.vertexCount).rowwise().mean();
}

}  // namespace

std::string_view partRoleName(PartRole role) { return kRoleNames[static_cast<std::size_t>(role)]; }

std::optional<PartRole> partRoleFromName(std::string_view name) {
  for (std::size_t i = 0; i < kRoleNames.size(); ++i)
    if (kRoleNames[i] == name) return kPartRoles[i];
  return std::nullopt;
}

PartRole guessPartRole(std::string_view submeshName, std::string_view materialName, HeadSide side) {
  const Words w(submeshName, materialName);
  // Shading shells and films another renderer needed (ambient-occlusion and blend shells over
  // the eyes, a tear film: Lacrima draws its own wet eyes and tears) are left out; cards that sit
  // on the skin ride on it. Both first: "EyeBlend", "eyelash" also say "eye".
  if (w.contains({"lacrimal", "tear", "occlusion", "blend"})) return PartRole::Ignored;
  if (w.contains({"lash", "brow", "caruncle"})) return PartRole::Attached;
  HeadSide named = w.side();
  if (named == HeadSide::Unknown) named = side;
  if (isCornea(w)) return named == HeadSide::Right ? PartRole::CorneaRight : PartRole::CorneaLeft;
  if (isEye(w)) return named == HeadSide::Right ? PartRole::EyeRight : PartRole::EyeLeft;
  // Gums (also "GumsTongue") stay with the skull: a tongue sub-mesh with the gums in it would
  // drag them along with the jaw.
  if (w.contains({"gum"})) return PartRole::TeethUpper;
  if (isTeeth(w))
    return w.contains({"lower", "bottom", "jaw"}) ? PartRole::TeethLower : PartRole::TeethUpper;
  if (w.contains({"tongue"})) return PartRole::Tongue;
  if (w.contains({"skin", "face", "head", "body"})) return PartRole::Skin;
  return PartRole::Rigid;
}

std::vector<PartRole> guessPartRoles(const HeadMesh& mesh) {
  const auto& parts = mesh.submeshes;
  const auto material = [&](const HeadSubmesh& p) -> std::string_view {
    return p.material >= 0 && p.material < static_cast<int>(mesh.materials.size())
               ? std::string_view(mesh.materials[static_cast<std::size_t>(p.material)].name)
               : std::string_view();
  };
  std::vector<PartRole> roles;
  roles.reserve(parts.size());
  // Eyes and corneas whose names give no side, and teeth whose names give no half.
  std::vector<std::size_t> unsidedEyes, unsidedCorneas, unsplitTeeth;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    roles.push_back(guessPartRole(parts[i].name, material(parts[i])));
    const Words w(parts[i].name, material(parts[i]));
    const bool eyeRole = roles[i] == PartRole::EyeLeft || roles[i] == PartRole::CorneaLeft;
    if (eyeRole && w.side() == HeadSide::Unknown)
      (roles[i] == PartRole::EyeLeft ? unsidedEyes : unsidedCorneas).push_back(i);
    if (roles[i] == PartRole::TeethUpper && isTeeth(w) && !w.contains({"gum"}) &&
        !namesTeethHalf(w))
      unsplitTeeth.push_back(i);
  }
  // The side of the head: +x is the face's own left in the face frame. Each unnamed eye is
  // compared with the mean of the unnamed ones, so a pair splits one each way.
  for (auto [group, left, right] :
       {std::tuple{&unsidedEyes, PartRole::EyeLeft, PartRole::EyeRight},
        std::tuple{&unsidedCorneas, PartRole::CorneaLeft, PartRole::CorneaRight}}) {
    if (group->size() < 2) continue;
    float mean = 0;
    for (std::size_t i : *group) mean += centre(mesh, parts[i]).x();
    mean /= static_cast<float>(group->size());
    for (std::size_t i : *group) roles[i] = centre(mesh, parts[i]).x() >= mean ? left : right;
  }
  if (unsplitTeeth.size() == 2) {
    const std::size_t a = unsplitTeeth[0], b = unsplitTeeth[1];
    roles[centre(mesh, parts[a]).y() < centre(mesh, parts[b]).y() ? a : b] = PartRole::TeethLower;
  }
  if (std::find(roles.begin(), roles.end(), PartRole::Skin) == roles.end()) {
    std::optional<std::size_t> largest;
    for (std::size_t i = 0; i < parts.size(); ++i)
      if (roles[i] == PartRole::Rigid &&
          (!largest || parts[i].triangles.size() > parts[*largest].triangles.size()))
        largest = i;
    if (largest) roles[*largest] = PartRole::Skin;
  }
  return roles;
}

}  // namespace lacrima::editing
