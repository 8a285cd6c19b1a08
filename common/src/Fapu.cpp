#include <lacrima/common/Fapu.h>

#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lacrima::inline common {
namespace {

// Collects every bad distance so that one message tells the user all that is wrong with
// a face (a mirrored face breaks ES0 and MW0 at once).
class Problems {
 public:
  void check(const char* label, double value, const char* expectation) {
    if (std::isfinite(value) && value > 0) return;
    std::ostringstream out;
    out.imbue(std::locale::classic());  // '.' decimals whatever the user's locale
    out << label << " = " << value
        << (std::isfinite(value) ? " is not positive: " : " is not finite: ") << expectation;
    messages_.push_back(out.str());
  }

  void throwIfAny() const {
    if (messages_.empty()) return;
    std::string all = "cannot compute the FAPUs: ";
    for (std::size_t i = 0; i < messages_.size(); ++i) {
      if (i > 0) all += "; ";
      all += messages_[i];
    }
    throw std::invalid_argument(all);
  }

 private:
  std::vector<std::string> messages_;
};

}  // namespace

FapuSet computeFapu(const FapuReferencePoints& p) {
  const double irisLeft = p.upperLidLeft.y() - p.lowerLidLeft.y();
  const double irisRight = p.upperLidRight.y() - p.lowerLidRight.y();
  FapuSet set;
  set.irisd0 = 0.5 * (irisLeft + irisRight);
  set.es0 = p.pupilLeft.x() - p.pupilRight.x();
  set.ens0 = 0.5 * (p.pupilLeft.y() + p.pupilRight.y()) - p.noseBottom.y();
  set.mns0 = p.noseBottom.y() - p.innerUpperLip.y();
  set.mw0 = p.lipCornerLeft.x() - p.lipCornerRight.x();

  Problems problems;
  // Each eye on its own: a shut or inverted eye would otherwise hide behind a healthy mean.
  problems.check("IRISD0 left eye height", irisLeft,
                 "the upper eyelid mid-point 3.1 must lie above (+y) the lower eyelid "
                 "mid-point 3.3");
  problems.check("IRISD0 right eye height", irisRight,
                 "the upper eyelid mid-point 3.2 must lie above (+y) the lower eyelid "
                 "mid-point 3.4");
  problems.check("ES0", set.es0,
                 "the left pupil 3.5 must lie at +x (the face's own left) of the right "
                 "pupil 3.6");
  problems.check("ENS0", set.ens0,
                 "the pupils 3.5 and 3.6 (mean y) must lie above (+y) the nose bottom 9.15");
  problems.check("MNS0", set.mns0,
                 "the nose bottom 9.15 must lie above (+y) the inner upper lip mid-point 2.2");
  problems.check("MW0", set.mw0,
                 "the left outer lip corner 8.3 must lie at +x (the face's own left) of the "
                 "right outer lip corner 8.4");
  problems.throwIfAny();
  return set;
}

double FapuSet::unitValue(FapUnit unit) const {
  switch (unit) {
    case FapUnit::None:
      return 0.0;
    case FapUnit::IRISD:
      return irisd0 / kDivisor;
    case FapUnit::ES:
      return es0 / kDivisor;
    case FapUnit::ENS:
      return ens0 / kDivisor;
    case FapUnit::MNS:
      return mns0 / kDivisor;
    case FapUnit::MW:
      return mw0 / kDivisor;
    case FapUnit::AU:
      return kAngleUnit;
    case FapUnit::Particles:
      return 1.0;
  }
  return 0.0;
}

}  // namespace lacrima::inline common
