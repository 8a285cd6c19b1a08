#include "HeadLook.h"

#include "HeadGeometry.h"
#include "TearLayers.h"
#include "TextureUpload.h"

#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/scene/OverlayMasks.h>
#include <lacrima/scene/OverlayTextures.h>
#include <lacrima/scene/SkinDetail.h>
#include <lacrima/scene/UntexturedParts.h>

#include <OgreGpuProgramParams.h>
#include <OgreLogManager.h>
#include <OgreMaterialManager.h>
#include <OgrePass.h>
#include <OgreSubEntity.h>
#include <OgreTechnique.h>
#include <OgreTextureManager.h>

#include <QImageReader>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace lacrima::scene::detail {
namespace {

QImage readTexture(const std::string& path) {
  if (path.empty()) return {};
  QImageReader reader(QString::fromStdString(path));
  QImage image = reader.read();
  if (image.isNull())
    Ogre::LogManager::getSingleton().logWarning("Lacrima: texture " + path + " unreadable (" +
                                                reader.errorString().toStdString() +
                                                "); using plain colour");
  return image;
}

Ogre::Vector4 toOgre(const Eigen::Vector4f& v) { return {v.x(), v.y(), v.z(), v.w()}; }

}  // namespace

HeadLook::HeadLook(OgreRuntime& runtime, const HeadMesh& head, HeadGeometry& geometry)
    : runtime_(runtime) {
  const std::string& group = runtime.resourceGroup();
  auto& materials = Ogre::MaterialManager::getSingleton();
  std::map<int, QImage> images;
  auto imageOf = [&](int material) -> const QImage& {
    auto it = images.find(material);
    if (it == images.end()) {
      QImage image;
      if (material >= 0 && material < static_cast<int>(head.materials.size()))
        image = readTexture(head.materials[static_cast<std::size_t>(material)].diffuseTexture);
      it = images.emplace(material, std::move(image)).first;
    }
    return it->second;
  };
  std::map<int, Ogre::TexturePtr> diffuse;
  auto diffuseOf = [&](int material) {
    auto it = diffuse.find(material);
    if (it == diffuse.end()) it = diffuse.emplace(material, texture(imageOf(material), true)).first;
    return it->second;
  };

  for (std::size_t s = 0; s < head.submeshes.size(); ++s) {
    Ogre::SubEntity* entity = geometry.subEntity(s);
    if (!entity) continue;
    const HeadSubmesh& sub = head.submeshes[s];
    const HeadMaterial fallback;
    const HeadMaterial& look =
        sub.material >= 0 && sub.material < static_cast<int>(head.materials.size())
            ? head.materials[static_cast<std::size_t>(sub.material)]
            : fallback;
    // An untextured part of a custom head: a generated eye, or a colour for its kind.
    const bool generatedEye = drawsGeneratedEye(head, sub);
    const std::optional<UntexturedKind> untextured = untexturedKind(sub, look);
    const Eigen::Vector4f colour = untextured ? untexturedColour(*untextured) : look.diffuse;
    // Parts the rig leaves out (tear films, occlusion shells) are not drawn; nor is a lash shell
    // without its texture, which would only hide the eye behind a solid band.
    if (sub.role == "ignored" || untextured == UntexturedKind::Lashes) {
      entity->setVisible(false);
      continue;
    }
    Part part;
    part.entity = entity;
    if (sub.name == "skin")
      part.role = Role::Skin;
    else if (sub.name == "eye_l" || sub.name == "eye_r" || generatedEye)
      part.role = Role::Eye;
    else if (sub.name == "cornea_l" || sub.name == "cornea_r")
      part.role = Role::Cornea;
    else if (look.transparent)
      part.role = Role::Card;
    part.eye = eyeSideOf(sub);

    static const std::map<Role, const char*> kBase{{Role::Skin, "Lacrima/Skin"},
                                                   {Role::Eye, "Lacrima/Eye"},
                                                   {Role::Cornea, "Lacrima/Cornea"},
                                                   {Role::Card, "Lacrima/Card"},
                                                   {Role::Lit, "Lacrima/Lit"}};
    Ogre::MaterialPtr material =
        materials.getByName(kBase.at(part.role), group)
            ->clone(runtime.uniqueName("material/" + sub.name), true, group);
    Ogre::Pass* pass = material->getTechnique(0)->getPass(0);
    const auto fragment = pass->getFragmentProgramParameters();
    switch (part.role) {
      case Role::Skin: {
        // The skin's texture gets its uv islands padded (seams otherwise show as lines); the
        // redness layer is made from the padded texture so both stay aligned.
        const QImage skin = padUvIslands(imageOf(sub.material), head, sub);
        const Ogre::TexturePtr layers[] = {
            texture(skin, true), texture(paintOverlayMask(head, overlayVertexWeights(head)), false),
            texture(makeIrritatedSkin(skin), true)};
        // The same layers close up, with the relief (setDetailStrength switches).
        part.closeUp = materials.getByName("Lacrima/SkinDetail", group)
                           ->clone(runtime.uniqueName("material/" + sub.name), true, group);
        Ogre::Pass* close = part.closeUp->getTechnique(0)->getPass(0);
        for (Ogre::Pass* p : {pass, close}) {
          for (unsigned short unit = 0; unit < 3; ++unit)
            p->getTextureUnitState(unit)->setTexture(layers[unit]);
          p->getFragmentProgramParameters()->setNamedConstant("materialColour",
                                                              toOgre(look.diffuse));
        }
        close->getTextureUnitState("detail")->setTexture(texture(makeSkinDetailNormals(), true));
        close->getFragmentProgramParameters()->setNamedConstant("detailTiling",
                                                                skinDetailTiling(head));
        part.closeUp->load();
        materials_.push_back(part.closeUp);
        break;
      }
      case Role::Eye: {
        if (generatedEye && !generatedEyeTexture_) {
          const QImage eye = generatedEyeTexture();
          generatedEyeTexture_ = texture(eye, true);
          generatedWetEye_ = texture(makeWetEye(eye), true);
        }
        pass->getTextureUnitState(0)->setTexture(generatedEye ? generatedEyeTexture_
                                                              : diffuseOf(sub.material));
        pass->getTextureUnitState(1)->setTexture(
            generatedEye ? generatedWetEye_ : texture(makeWetEye(imageOf(sub.material)), true));
        // The generated picture carries the eye's colours; the file's grey would only dim it.
        fragment->setNamedConstant("materialColour",
                                   generatedEye ? Ogre::Vector4(1, 1, 1, 1) : toOgre(look.diffuse));
        break;
      }
      case Role::Cornea:
        break;
      case Role::Card:
        pass->getTextureUnitState(0)->setTexture(diffuseOf(sub.material));
        fragment->setNamedConstant("materialColour", toOgre(colour));
        entity->setRenderQueueGroup(kCardQueue);
        break;
      case Role::Lit:
        pass->getTextureUnitState(0)->setTexture(diffuseOf(sub.material));
        fragment->setNamedConstant("materialColour", toOgre(colour));
        fragment->setNamedConstant(
            "specularColour",
            Ogre::Vector4(look.specular.x(), look.specular.y(), look.specular.z(), look.shininess));
        break;
    }
    material->load();
    entity->setMaterial(material);
    part.whole = material;
    entity->setCustomParameter(0, Ogre::Vector4(0, 0, 0, 0));
    entity->setCustomParameter(1, Ogre::Vector4(0, 0, 0, 0));
    materials_.push_back(material);
    parts_.push_back(part);
  }
}

HeadLook::~HeadLook() {
  // Sub-entities die with the geometry (destroyed after this); the materials they point to
  // must not be removed while anything still renders, and nothing renders during destruction.
  auto& materials = Ogre::MaterialManager::getSingleton();
  for (auto& material : materials_) {
    const std::string name = material->getName(), group = material->getGroup();
    material.reset();
    materials.remove(name, group);
  }
  auto& textures = Ogre::TextureManager::getSingleton();
  for (auto& texture : textures_) {
    const std::string name = texture->getName(), group = texture->getGroup();
    texture.reset();
    textures.remove(name, group);
  }
}

Ogre::TexturePtr HeadLook::texture(const QImage& image, bool mipmaps) {
  Ogre::TexturePtr created =
      uploadTexture(image, runtime_.uniqueName("texture"), runtime_.resourceGroup(), mipmaps);
  textures_.push_back(created);
  return created;
}

void HeadLook::setOverlays(const playback::OverlayWeights& weights, bool enabled) {
  auto unit = [enabled](double w) {
    return enabled && std::isfinite(w) ? static_cast<float>(std::clamp(w, 0.0, 1.0)) : 0.0f;
  };
  const float redness = unit(weights.redness), blush = unit(weights.blush);
  const float wet[2] = {unit(weights.wetEyes[0]), unit(weights.wetEyes[1])};
  for (const Part& part : parts_) {
    Ogre::Vector4 value(0, 0, 0, 0);
    if (part.role == Role::Skin) value = Ogre::Vector4(redness, 0, blush, 0);
    if ((part.role == Role::Eye || part.role == Role::Cornea) && part.eye >= 0)
      value = Ogre::Vector4(redness, wet[part.eye], 0, 0);
    part.entity->setCustomParameter(0, value);
  }
}

void HeadLook::setDetailStrength(float strength) {
  const float s = std::isfinite(strength) ? std::clamp(strength, 0.0f, 1.0f) : 0.0f;
  for (Part& part : parts_) {
    if (!part.closeUp) continue;
    part.entity->setCustomParameter(1, Ogre::Vector4(s, 0, 0, 0));
    // Swapping materials (both loaded at start-up) costs nothing; a relief weighted 0 in the
    // same program would still be fetched: llvmpipe runs both sides of a uniform branch.
    if ((s > 0) != part.showingCloseUp) {
      part.showingCloseUp = s > 0;
      part.entity->setMaterial(part.showingCloseUp ? part.closeUp : part.whole);
    }
  }
}

}  // namespace lacrima::scene::detail
