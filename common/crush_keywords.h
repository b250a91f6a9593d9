/* Crushing model (plain C++): the one way the plugin's commands read their arguments.

   Each command declares a table: keyword name, what its values must be (the text every error
   quotes), how many values it reads and where it stores them, and whether it is required. Parsing,
   the error texts and the list of accepted keywords all come from the table:

     KeywordTable t;
     t.number("alpha", "a value in [0, 1)", in_range(0.0, 1.0, false), alpha, true)
      .yes_no("moments", moments);
     t.parse(args);      // ModelError "keyword 'alpha' expects a value in [0, 1), got '1.5'"

   Messages do not name the command: the LIGGGHTS adapter passes them to error->fix_error() or
   error->compute_error(), which name the style and ID (input_keyword.h). */
#ifndef CRUSH_KEYWORDS_H
#define CRUSH_KEYWORDS_H

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace crush {

// Accepted ranges of numbers.
using Accept = std::function<bool(double)>;
Accept positive();                                        // > 0
Accept at_least(double low);                              // >= low
Accept below(double high);                                // < high
Accept in_range(double low, double high, bool high_closed);  // [low, high] or [low, high)
Accept open_closed(double low, double high);              // (low, high]

class KeywordTable {
 public:
  KeywordTable() = default;
  KeywordTable(const KeywordTable &) = delete;  // its readers refer to the table itself
  KeywordTable &operator=(const KeywordTable &) = delete;

  // Reads the values after the keyword at args[at] (args[at + 1] ...); returns how many it read.
  using Reader = std::function<std::size_t(const std::vector<std::string> &args, std::size_t at)>;

  KeywordTable &add(const std::string &name, const std::string &expects, Reader read, bool required = false);
  // One finite number within the accepted range.
  KeywordTable &number(const std::string &name, const std::string &expects, Accept ok, double &target,
                       bool required = false);
  // One whole number >= low.
  KeywordTable &integer(const std::string &name, const std::string &expects, long low, long &target,
                        bool required = false);
  // One of the given words; target is its index.
  KeywordTable &choice(const std::string &name, const std::vector<std::string> &words, int &target);
  KeywordTable &yes_no(const std::string &name, bool &target);
  // One or more ascending numbers > 0, up to the next keyword (sieve sizes, output stresses).
  KeywordTable &ascending(const std::string &name, const std::string &expects, std::vector<double> &target,
                          bool required = false);
  // One word, stored as given.
  KeywordTable &text(const std::string &name, const std::string &expects, std::string &target);

  // Parses args[first ...] as keyword/value groups; a ModelError names the keyword and what it expects.
  void parse(const std::vector<std::string> &args, std::size_t first = 0) const;

  bool is_keyword(const std::string &word) const;
  // "a, b or c": the keywords in the order declared.
  std::string accepted() const;
  // Throws ModelError "keyword '<name>' expects <expects>, got '<got>'" (or without ", got" when got is empty).
  [[noreturn]] void fail(const std::string &name, const std::string &got) const;

  // The number args[at] for keyword name, or fail().
  double value(const std::string &name, const std::vector<std::string> &args, std::size_t at) const;
  // The whole number args[at] in [low, high] for keyword name, or fail().
  long whole(const std::string &name, const std::vector<std::string> &args, std::size_t at, long low,
             long high) const;

 private:
  struct Keyword {
    std::string name, expects;
    Reader read;
    bool required;
  };
  const Keyword &find(const std::string &name) const;
  std::vector<Keyword> keywords_;
};

}  // namespace crush

#endif
