// Text measured and fitted once while it is unchanged: a view that lays out and paints the same
// titles, caption lines and labels every frame asks Qt to shape each of them once, not once a
// frame. Only the numbers that change from frame to frame are measured again.
//
// Each answer is the one Qt gives for the same font, width and text (the same strings, so the
// same pixels once painted); the font is told apart by QFont::key(), widths to the bit.
#pragma once

#include <QFont>
#include <QHash>
#include <QString>
#include <QStringList>
#include <functional>
#include <utility>
#include <vector>

namespace oflab {

class TextCache {
 public:
  // `measure()` (the width of `text` in `font`, pixels), computed the first time it is asked.
  int advance(const QFont& font, const QString& text, const std::function<int()>& measure);
  // `wrap()` (`text` broken into lines of at most `width` pixels in `font`), computed the first
  // time it is asked.
  QStringList lines(const QFont& font, double width, const QString& text,
                    const std::function<QStringList()>& wrap);
  // QFontMetrics(font).elidedText(text, Qt::ElideRight, width).
  QString elided(const QFont& font, const QString& text, int width);

  // Entries kept of each kind; past it they are all dropped (texts whose numbers change each
  // frame would otherwise pile up).
  static constexpr int kMaxEntries = 2048;

 private:
  const QString& font_key(const QFont& font);  // font.key(), kept for the fonts last asked

  std::vector<std::pair<QFont, QString>> font_keys_;
  QHash<QString, int> advances_;
  QHash<QString, QStringList> lines_;
  QHash<QString, QString> elided_;
};

}  // namespace oflab
