/* Crushing model (plain C++): keyword tables of the plugin's commands (see crush_keywords.h). */
#include "crush_keywords.h"

#include <cmath>
#include <set>

#include "crush_model_error.h"
#include "crush_number.h"

namespace crush {

Accept positive() { return [](double v) { return v > 0.0; }; }
Accept at_least(double low) { return [low](double v) { return v >= low; }; }
Accept below(double high) { return [high](double v) { return v < high; }; }
Accept in_range(double low, double high, bool high_closed)
{
  return [=](double v) { return v >= low && (high_closed ? v <= high : v < high); };
}
Accept open_closed(double low, double high) { return [=](double v) { return v > low && v <= high; }; }

KeywordTable &KeywordTable::add(const std::string &name, const std::string &expects, Reader read, bool required)
{
  keywords_.push_back({name, expects, std::move(read), required});
  return *this;
}

double KeywordTable::value(const std::string &name, const std::vector<std::string> &args, std::size_t at) const
{
  if (at >= args.size()) fail(name, "");
  double v = 0.0;
  if (!parse_finite(args[at], v)) fail(name, args[at]);
  return v;
}

long KeywordTable::whole(const std::string &name, const std::vector<std::string> &args, std::size_t at, long low,
                         long high) const
{
  const double v = value(name, args, at);
  if (!(v >= static_cast<double>(low)) || v > static_cast<double>(high) || v != std::floor(v)) fail(name, args[at]);
  return static_cast<long>(v);
}

KeywordTable &KeywordTable::number(const std::string &name, const std::string &expects, Accept ok, double &target,
                                   bool required)
{
  return add(name, expects, [this, name, ok, &target](const std::vector<std::string> &args, std::size_t at) {
    const double v = value(name, args, at + 1);
    if (!ok(v)) fail(name, args[at + 1]);
    target = v;
    return std::size_t(1);
  }, required);
}

KeywordTable &KeywordTable::integer(const std::string &name, const std::string &expects, long low, long &target,
                                    bool required)
{
  return add(name, expects, [this, name, low, &target](const std::vector<std::string> &args, std::size_t at) {
    // up to what a double holds exactly
    target = whole(name, args, at + 1, low, 9000000000000000L);
    return std::size_t(1);
  }, required);
}

KeywordTable &KeywordTable::choice(const std::string &name, const std::vector<std::string> &words, int &target)
{
  std::string expects;
  for (std::size_t k = 0; k < words.size(); k++)
    expects += (k == 0 ? "" : k + 1 == words.size() ? " or " : ", ") + ("'" + words[k] + "'");
  return add(name, expects, [this, name, words, &target](const std::vector<std::string> &args, std::size_t at) {
    if (at + 1 >= args.size()) fail(name, "");
    for (std::size_t k = 0; k < words.size(); k++)
      if (args[at + 1] == words[k]) {
        target = static_cast<int>(k);
        return std::size_t(1);
      }
    fail(name, args[at + 1]);
  });
}

KeywordTable &KeywordTable::yes_no(const std::string &name, bool &target)
{
  return add(name, "'yes' or 'no'", [this, name, &target](const std::vector<std::string> &args, std::size_t at) {
    if (at + 1 >= args.size() || (args[at + 1] != "yes" && args[at + 1] != "no"))
      fail(name, at + 1 < args.size() ? args[at + 1] : "");
    target = args[at + 1] == "yes";
    return std::size_t(1);
  });
}

KeywordTable &KeywordTable::ascending(const std::string &name, const std::string &expects, std::vector<double> &target,
                                      bool required)
{
  return add(name, expects, [this, name, &target](const std::vector<std::string> &args, std::size_t at) {
    std::size_t read = 0;
    for (std::size_t k = at + 1; k < args.size() && !is_keyword(args[k]); k++, read++) {
      const double v = value(name, args, k);
      if (!(v > 0.0) || (!target.empty() && v <= target.back())) fail(name, args[k]);
      target.push_back(v);
    }
    if (read == 0) fail(name, "");
    return read;
  }, required);
}

KeywordTable &KeywordTable::text(const std::string &name, const std::string &expects, std::string &target)
{
  return add(name, expects, [this, name, &target](const std::vector<std::string> &args, std::size_t at) {
    if (at + 1 >= args.size()) fail(name, "");
    target = args[at + 1];
    return std::size_t(1);
  });
}

const KeywordTable::Keyword &KeywordTable::find(const std::string &name) const
{
  for (const Keyword &k : keywords_)
    if (k.name == name) return k;
  throw ModelError("unknown keyword '" + name + "' (expected " + accepted() + ")");
}

void KeywordTable::parse(const std::vector<std::string> &args, std::size_t first) const
{
  std::set<std::string> seen;
  for (std::size_t at = first; at < args.size();) {
    const Keyword &k = find(args[at]);
    seen.insert(k.name);
    at += 1 + k.read(args, at);
  }
  for (const Keyword &k : keywords_)
    if (k.required && !seen.count(k.name))
      throw ModelError("keyword '" + k.name + "' is required (" + k.expects + ")");
}

bool KeywordTable::is_keyword(const std::string &word) const
{
  for (const Keyword &k : keywords_)
    if (k.name == word) return true;
  return false;
}

std::string KeywordTable::accepted() const
{
  std::string list;
  for (std::size_t k = 0; k < keywords_.size(); k++)
    list += (k == 0 ? "" : k + 1 == keywords_.size() ? " or " : ", ") + keywords_[k].name;
  return list;
}

void KeywordTable::fail(const std::string &name, const std::string &got) const
{
  const Keyword &k = find(name);
  throw ModelError("keyword '" + name + "' expects " + k.expects + (got.empty() ? "" : ", got '" + got + "'"));
}

}  // namespace crush
