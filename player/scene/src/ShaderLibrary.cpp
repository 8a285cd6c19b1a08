#include "ShaderLibrary.h"

#include <OgreDataStream.h>
#include <OgreHighLevelGpuProgram.h>
#include <OgreHighLevelGpuProgramManager.h>
#include <OgreMaterialManager.h>
#include <OgreScriptCompiler.h>
#include <OgreTechnique.h>

#include <QDir>
#include <QFile>
#include <QRegularExpression>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace lacrima::scene::detail {
namespace {

const QString kShaderDir = QStringLiteral(":/lacrima/scene/shaders");
const QString kMaterialDir = QStringLiteral(":/lacrima/scene/materials");

QByteArray readResource(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly))
    throw std::runtime_error("Lacrima scene: built-in resource " + path.toStdString() +
                             " is missing");
  return file.readAll();
}

// Resolves `#include "file"` lines (one level is all the shaders use; nesting works too, and
// a file includes itself at most once per shader).
QByteArray withIncludes(const QString& name, QStringList& seen) {
  static const QRegularExpression include(QStringLiteral("^\\s*#include\\s+\"([^\"]+)\"\\s*$"));
  seen.append(name);
  QByteArray out;
  const QList<QByteArray> lines = readResource(kShaderDir + '/' + name).split('\n');
  for (const QByteArray& line : lines) {
    const auto match = include.match(QString::fromUtf8(line));
    if (!match.hasMatch()) {
      out += line + '\n';
      continue;
    }
    const QString target = match.captured(1);
    if (!seen.contains(target)) out += withIncludes(target, seen);
  }
  return out;
}

std::vector<Ogre::HighLevelGpuProgramPtr> createPrograms(const std::string& group) {
  std::vector<Ogre::HighLevelGpuProgramPtr> created;
  auto& programs = Ogre::HighLevelGpuProgramManager::getSingleton();
  const QStringList files =
      QDir(kShaderDir).entryList({QStringLiteral("*.vert"), QStringLiteral("*.frag")}, QDir::Files);
  for (const QString& file : files) {
    QStringList seen;
    const QByteArray source = withIncludes(file, seen);
    const auto type = file.endsWith(QLatin1String(".vert")) ? Ogre::GPT_VERTEX_PROGRAM
                                                            : Ogre::GPT_FRAGMENT_PROGRAM;
    auto program = programs.createProgram(file.toStdString(), group, "glsl", type);
    program->setSource(source.toStdString());
    created.push_back(program);
  }
  return created;
}

std::vector<std::string> materialNames(const std::string& group) {
  std::vector<std::string> names;
  auto it = Ogre::MaterialManager::getSingleton().getResourceIterator();
  while (it.hasMoreElements()) {
    const Ogre::ResourcePtr material = it.getNext();
    if (material->getGroup() == group) names.push_back(material->getName());
  }
  return names;
}

std::vector<std::string> parseMaterials(const std::string& group) {
  const std::vector<std::string> before = materialNames(group);
  const QStringList files =
      QDir(kMaterialDir).entryList({QStringLiteral("*.material")}, QDir::Files);
  for (const QString& file : files) {
    QByteArray text = readResource(kMaterialDir + '/' + file);
    Ogre::DataStreamPtr stream = std::make_shared<Ogre::MemoryDataStream>(
        "media/materials/" + file.toStdString(), text.data(), static_cast<std::size_t>(text.size()),
        false, true);
    Ogre::ScriptCompilerManager::getSingleton().parseScript(stream, group);
  }
  std::vector<std::string> added;
  for (const std::string& name : materialNames(group))
    if (std::find(before.begin(), before.end(), name) == before.end()) added.push_back(name);
  return added;
}

}  // namespace

void loadShaderLibrary(const std::string& group, const std::string& logPath) {
  const std::vector<Ogre::HighLevelGpuProgramPtr> programs = createPrograms(group);
  const std::vector<std::string> materials = parseMaterials(group);
  if (materials.empty())
    throw std::runtime_error(
        "Lacrima scene: media/materials defined no material (see the OGRE log " + logPath + ")");
  for (const std::string& name : materials) {
    Ogre::MaterialPtr material = Ogre::MaterialManager::getSingleton().getByName(name, group);
    material->load();
    if (material->getSupportedTechniques().empty())
      throw std::runtime_error("Lacrima scene: material " + name + " cannot be rendered: " +
                               material->getUnsupportedTechniquesExplanation() +
                               " (see the OGRE log " + logPath + ")");
  }
  for (const Ogre::HighLevelGpuProgramPtr& program : programs) {
    program->load();  // the ones no material uses were not compiled yet
    if (program->hasCompileError())
      throw std::runtime_error("Lacrima scene: shader media/shaders/" + program->getName() +
                               " does not compile (the compiler's message is in the OGRE log " +
                               logPath + ")");
  }
}

}  // namespace lacrima::scene::detail
