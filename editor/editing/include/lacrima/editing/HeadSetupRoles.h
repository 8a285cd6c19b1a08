#pragma once
// What each sub-mesh of an imported head is for (the Head workspace's parts table), and the
// first guess from its names.
//
// The roles map onto a feature-point file's "submeshes" (FeaturePointFile.h):
//   Skin                    -> skin        the deforming surface
//   EyeLeft,  CorneaLeft    -> eye_left    turn with FAPs 23/25 (a cornea goes with its eye)
//   EyeRight, CorneaRight   -> eye_right
//   TeethLower              -> jaw         follow the jaw
//   Tongue                  -> tongue
//   Attached                -> attached    ride on the skin (lashes, brows, tear films)
//   TeethUpper, Rigid,
//   Ignored                 -> (unlisted)  follow the head rotation only
// The Head workspace leaves attached and ignored parts out of picking: a click goes through
// lashes and tear films (which lie over the eye corners) to the skin or eye below.
#include <lacrima/common/HeadMesh.h>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace lacrima::editing {

enum class PartRole {
  Skin,
  EyeLeft,
  EyeRight,
  CorneaLeft,
  CorneaRight,
  TeethUpper,
  TeethLower,
  Tongue,
  Attached,
  Rigid,
  Ignored,
};

inline constexpr std::array kPartRoles{
    PartRole::Skin,        PartRole::EyeLeft,    PartRole::EyeRight,   PartRole::CorneaLeft,
    PartRole::CorneaRight, PartRole::TeethUpper, PartRole::TeethLower, PartRole::Tongue,
    PartRole::Attached,    PartRole::Rigid,      PartRole::Ignored};

// "skin", "eye_left", "cornea_left", "teeth_upper", ..., "ignored".
std::string_view partRoleName(PartRole role);
std::optional<PartRole> partRoleFromName(std::string_view name);

// Which side of the head a part without a side in its name sits on, when known.
enum class HeadSide { Unknown, Left, Right };

// The guess from a sub-mesh's name and its material's name (case and separators ignored):
//   lash, brow, lacrimal, tear, occlusion, blend, caruncle     -> Attached
//   cornea + side                                              -> CorneaLeft / CorneaRight
//   eye, iris, sclera, pupil, eyeball + side                   -> EyeLeft / EyeRight
//   gum (with or without teeth), teeth/tooth + upper/top       -> TeethUpper
//   teeth/tooth + lower/bottom/jaw                             -> TeethLower
//   tongue                                                     -> Tongue
//   skin, face, head, body                                     -> Skin
//   anything else                                              -> Rigid
// The side is read from the names ("left"/"right", a separate "l"/"r" token as in eye_l, EyeL,
// L_eye), else `side` is used; an eye or cornea with no side at all guesses EyeLeft/CorneaLeft.
// Teeth with no upper/lower guess TeethUpper (rigid with the head, the safe choice).
PartRole guessPartRole(std::string_view submeshName, std::string_view materialName,
                       HeadSide side = HeadSide::Unknown);

// guessPartRole for every sub-mesh of `mesh`, with the side of an unnamed eye taken from its
// centre's x against the other eye's (the face frame's +x is the face's own left) and, of two
// unnamed teeth parts, the lower centre (y) taken as TeethLower. When no part guesses Skin, the
// Rigid part with the most triangles becomes Skin. Guesses only: the user corrects them.
std::vector<PartRole> guessPartRoles(const HeadMesh& mesh);

}  // namespace lacrima::editing
