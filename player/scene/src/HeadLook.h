#pragma once
// Materials and textures of one head: each sub-mesh gets a clone of the base material for its
// role (media/materials/lacrima.material) with the head's texture and colours:
//   skin            Lacrima/Skin: diffuse, overlay mask (OverlayMasks.h), irritated skin layer;
//                   close up Lacrima/SkinDetail: the same and the tiling relief (SkinDetail.h)
//   eye_l, eye_r    Lacrima/Eye: diffuse, bloodshot sclera layer (its alpha: where the sclera is)
//   cornea_l/_r     Lacrima/Cornea: additive reflections only
//   transparent     Lacrima/Card: alpha-textured lashes and brows, drawn after the tears
//   anything else   Lacrima/Lit with the material's colour, specular and shininess
// A custom head's untextured parts (UntexturedParts.h): its eyes are Lacrima/Eye with the
// generated eye texture on projected uvs, grey skin and teeth get a skin tone and an ivory;
// grey lash shells and parts the rig ignores are not drawn.
// The overlay weights reach the shaders as custom parameter 0 of each sub-entity
// (x redness, y this eye's wetness, z blush; skin gets x and z, eyes and corneas x and y), and
// the strength of the skin's relief as custom parameter 1 (x), so changing them costs no
// material change.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/playback/FrameView.h>

#include <OgreMaterial.h>
#include <OgreTexture.h>

#include <QImage>

#include <vector>

namespace Ogre {
class SubEntity;
}

namespace lacrima::scene {
class OgreRuntime;
}

namespace lacrima::scene::detail {

class HeadGeometry;

class HeadLook {
 public:
  HeadLook(OgreRuntime& runtime, const HeadMesh& head, HeadGeometry& geometry);
  ~HeadLook();
  HeadLook(const HeadLook&) = delete;
  HeadLook& operator=(const HeadLook&) = delete;

  // Weights in [0, 1] (clamped); `enabled` false sets them all to 0 (no overlay at all).
  void setOverlays(const playback::OverlayWeights& weights, bool enabled);
  // The skin's fine relief (SkinDetail.h), 0 (the skin's plain material, no relief fetched) to
  // 1; clamped.
  void setDetailStrength(float strength);

 private:
  enum class Role { Skin, Eye, Cornea, Card, Lit };
  struct Part {
    Ogre::SubEntity* entity = nullptr;
    Role role = Role::Lit;
    int eye = -1;               // 0 left, 1 right
    Ogre::MaterialPtr whole;    // the material it starts with
    Ogre::MaterialPtr closeUp;  // skin only: the same layers and the fine relief
    bool showingCloseUp = false;
  };
  Ogre::TexturePtr texture(const QImage& image, bool mipmaps);

  OgreRuntime& runtime_;
  std::vector<Part> parts_;
  std::vector<Ogre::MaterialPtr> materials_;
  std::vector<Ogre::TexturePtr> textures_;
  Ogre::TexturePtr generatedEyeTexture_, generatedWetEye_;  // shared by both generated eyes
};

}  // namespace lacrima::scene::detail
