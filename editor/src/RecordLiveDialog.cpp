// RecordLiveDialog (RecordLiveDialog.h): the URL, the count-in and the channel groups of a take.
#include <lacrima/editor/RecordLiveDialog.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace lacrima::editor {

namespace {

// The groups a take can key, in the FAP table's order (visemes and expressions are high-level
// codes the recording ignores).
constexpr FapGroup kGroups[] = {FapGroup::JawChinInnerLips,
                                FapGroup::Eyes,
                                FapGroup::Eyebrows,
                                FapGroup::Cheeks,
                                FapGroup::Tongue,
                                FapGroup::Head,
                                FapGroup::OuterLips,
                                FapGroup::Nose,
                                FapGroup::Ears,
                                FapGroup::Tears};

QString groupLabel(FapGroup group) {
  QString text = QString::fromUtf8(toString(group).data(), toString(group).size());
  if (!text.isEmpty()) text[0] = text[0].toUpper();
  return text;
}

}  // namespace

std::optional<ChannelMask> recordedChannels(const RecordLiveSettings& settings,
                                            const ChannelMask& selected) {
  const bool restrictToSelection = settings.onlySelected && selected.any();
  bool allGroups = true;
  for (const FapGroup group : kGroups)
    allGroups = allGroups && !settings.skippedGroups.count(group);
  if (allGroups && !restrictToSelection) return ChannelMask{};  // all the stream sets
  ChannelMask channels;
  for (const FapInfo& info : fapTable())
    if (info.group != FapGroup::VisemeExpression && !settings.skippedGroups.count(info.group))
      channels.set(static_cast<std::size_t>(channelIndex(info.number)));
  if (restrictToSelection) channels &= selected;
  if (channels.none()) return std::nullopt;
  return channels;
}

RecordLiveDialog::RecordLiveDialog(const RecordLiveSettings& settings, const ChannelMask& selected,
                                   QWidget* parent)
    : QDialog(parent), selected_(selected) {
  setWindowTitle(tr("Record live"));
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  url_ = new QLineEdit(settings.url, this);
  url_->setToolTip(tr("fap+tcp://HOST:PORT, fap+udp://HOST:PORT or livelink+udp://HOST:PORT"));
  form->addRow(tr("Listen at:"), url_);
  countIn_ = new QDoubleSpinBox(this);
  countIn_->setRange(0, RecordLiveSettings::kMaxCountIn);
  countIn_->setSingleStep(0.5);
  countIn_->setDecimals(1);
  countIn_->setSuffix(tr(" s"));
  countIn_->setValue(settings.countIn);
  countIn_->setToolTip(tr("Time to get ready: the stream is shown but not recorded"));
  form->addRow(tr("Count-in:"), countIn_);
  layout->addLayout(form);

  auto* box = new QGroupBox(tr("Channels to key"), this);
  auto* grid = new QGridLayout(box);
  int i = 0;
  for (const FapGroup group : kGroups) {
    auto* check = new QCheckBox(groupLabel(group), box);
    check->setChecked(!settings.skippedGroups.count(group));
    grid->addWidget(check, i / 2, i % 2);
    groups_.emplace_back(group, check);
    connect(check, &QCheckBox::toggled, this, &RecordLiveDialog::update);
    ++i;
  }
  onlySelected_ = new QCheckBox(
      tr("Only the %n channel(s) selected", nullptr, static_cast<int>(selected.count())), box);
  onlySelected_->setChecked(settings.onlySelected);
  onlySelected_->setEnabled(selected.any());
  if (!selected.any()) onlySelected_->setText(tr("Only the selected channels (none selected)"));
  connect(onlySelected_, &QCheckBox::toggled, this, &RecordLiveDialog::update);
  grid->addWidget(onlySelected_, (i + 1) / 2, 0, 1, 2);
  layout->addWidget(box);

  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons_->button(QDialogButtonBox::Ok)->setText(tr("Record"));
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(url_, &QLineEdit::textChanged, this, &RecordLiveDialog::update);
  layout->addWidget(buttons_);
  update();
}

RecordLiveSettings RecordLiveDialog::settings() const {
  RecordLiveSettings s;
  s.url = url_->text().trimmed();
  s.countIn = countIn_->value();
  for (const auto& [group, check] : groups_)
    if (!check->isChecked()) s.skippedGroups.insert(group);
  s.onlySelected = onlySelected_->isChecked();
  return s;
}

QCheckBox* RecordLiveDialog::groupBox(FapGroup group) const {
  for (const auto& [g, check] : groups_)
    if (g == group) return check;
  return nullptr;
}

// Record is offered only when there is a URL and something to key.
void RecordLiveDialog::update() {
  const bool ok = !url_->text().trimmed().isEmpty() && recordedChannels(settings(), selected_);
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(ok);
}

}  // namespace lacrima::editor
