#pragma once
// Clients for the live suites, written from the published layouts, not from Lacrima's own
// writers: Greta-style FAP text (the .fap mask line and value line per frame, as
// FAP_FILE_FORMAT.md describes) and Live Link Face packets (the layout PyLiveLinkFace and
// think-biq/LLV document: docs/live.md).
#include <QByteArray>
#include <QCoreApplication>
#include <QDataStream>
#include <QElapsedTimer>
#include <QIODevice>

#include <array>
#include <functional>
#include <map>
#include <string>

namespace lacrima::live::test {

// A mask line of 68 (or 70) tokens setting the FAPs in `values`, and the value line after it:
// frame number, then the values in FAP order. Greta writes integers.
inline QByteArray gretaFrame(int number, const std::map<int, int>& values, int tokens = 68) {
  QByteArray mask, line = QByteArray::number(number);
  for (int fap = 1; fap <= tokens; ++fap) {
    const auto it = values.find(fap);
    mask += it != values.end() ? "1" : "0";
    mask += fap < tokens ? " " : "\n";
    if (it != values.end()) line += ' ' + QByteArray::number(it->second);
  }
  return mask + line + '\n';
}

// Value indices of the Live Link packet (ARKit's order, then the angles).
enum LiveLinkIndex {
  kEyeBlinkLeft = 0,
  kJawOpen = 17,
  kBrowInnerUp = 43,
  kHeadYaw = 52,
  kHeadPitch = 53,
  kLeftEyeYaw = 55
};

// A Live Link Face packet: version 6, device id and subject name (each a big-endian uint32
// length and its bytes), frame number, sub-frame (float), rate numerator and denominator, the
// count 61 (one byte) and 61 big-endian floats.
inline QByteArray liveLinkPacket(const std::array<float, 61>& values, qint32 frame = 0,
                                 qint32 fps = 60, quint8 count = 61, quint8 version = 6) {
  QByteArray bytes;
  QDataStream out(&bytes, QIODevice::WriteOnly);
  out.setByteOrder(QDataStream::BigEndian);
  out.setFloatingPointPrecision(QDataStream::SinglePrecision);
  const QByteArray device = "$0F4C8B52-7E0A-4C3B-9D15-6A2E1B7C9D04";
  const QByteArray subject = "iPhone13";
  out << version;
  out << quint32(device.size());
  out.writeRawData(device.constData(), device.size());
  out << quint32(subject.size());
  out.writeRawData(subject.constData(), subject.size());
  out << frame << 0.0F << fps << qint32(1) << count;
  for (int i = 0; i < count && i < 61; ++i) out << values[static_cast<std::size_t>(i)];
  return bytes;
}

// Runs the event loop until `done` or `ms` pass.
inline bool waitFor(const std::function<bool()>& done, int ms = 20000) {
  QElapsedTimer timer;
  timer.start();
  while (!done() && timer.elapsed() < ms) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
  return done();
}

}  // namespace lacrima::live::test
