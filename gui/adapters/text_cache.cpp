#include "adapters/text_cache.h"

#include <QFontMetrics>

namespace oflab {
namespace {

// One key of the font's key, a width and the text (a separator no caption holds between them).
QString key_of(const QString& font_key, double width, const QString& text) {
  return font_key + QChar(0x1f) + QString::number(width, 'g', 17) + QChar(0x1f) + text;
}

template <class Value, class Make>
Value kept(QHash<QString, Value>& table, const QString& key, const Make& make) {
  const auto found = table.constFind(key);
  if (found != table.constEnd()) return found.value();
  if (table.size() >= TextCache::kMaxEntries) table.clear();
  const Value value = make();
  table.insert(key, value);
  return value;
}

}  // namespace

const QString& TextCache::font_key(const QFont& font) {
  // QFont::key() builds its string anew at each call; the views ask in a few fonts in turn.
  for (const auto& known : font_keys_) {
    if (known.first == font) return known.second;
  }
  if (font_keys_.size() >= 16) font_keys_.clear();
  font_keys_.emplace_back(font, font.key());
  return font_keys_.back().second;
}

int TextCache::advance(const QFont& font, const QString& text,
                       const std::function<int()>& measure) {
  return kept(advances_, key_of(font_key(font), 0.0, text), measure);
}

QStringList TextCache::lines(const QFont& font, double width, const QString& text,
                             const std::function<QStringList()>& wrap) {
  return kept(lines_, key_of(font_key(font), width, text), wrap);
}

QString TextCache::elided(const QFont& font, const QString& text, int width) {
  return kept(elided_, key_of(font_key(font), width, text),
              [&] { return QFontMetrics(font).elidedText(text, Qt::ElideRight, width); });
}

}  // namespace oflab
