/// @file check_page.hpp
/// `./workbook check NN --html`: the check's table as one page, with every exercise's verdict, what
/// was found (got/want, the hint, where the code is) and the pictures its failing tests left, which
/// the page carries inside it, so that it can be opened, moved or mailed as one file.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace wb::test {

/// One exercise's row of the check's table.
struct PageRow {
  std::string id;                    ///< the exercise, "01.2"
  std::string status;                ///< passes, wrong, error, not implemented...
  std::string title;                 ///< the exercise's title
  std::string headline;              ///< the verdict's first line
  std::vector<std::string> details;  ///< lines below the headline; "picture: PATH (caption)" shows PATH
  std::string where;                 ///< "labs/NN/file:line" of a wrong exercise, or ""
};

/// Writes the page to `file`; false when it could not be written.
bool writeCheckPage(const std::filesystem::path& file, const std::string& heading, const std::vector<PageRow>& rows,
                    const std::string& summary);

}  // namespace wb::test
