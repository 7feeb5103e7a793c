#pragma once
/// *CASE (LS-DYNA's multiple-case decks, run by `lsdyna case`): a master case CASEID with a job
/// name JOBID, command-line options, and the subcases it reads. A case's model is every keyword
/// outside the *CASE_BEGIN_n / *CASE_END_n blocks (and without "CID=n" on its keyword line) plus
/// the keywords of the subcases it lists. The lexer tags each keyword with its subcases
/// (KeywordBlock::subcases); keep_case drops those of the other subcases.
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "deck/deck.hpp"

namespace mcdyna::deck {

struct Case {
  long id = 0;                        ///< CASEID
  std::string job;                    ///< JOBID (its outputs' name); "case<CASEID>" when blank
  std::vector<std::string> commands;  ///< command-line options of the case (not used)
  std::vector<long> subcases;         ///< the n of the *CASE_BEGIN_n blocks it reads
  core::SourceLoc loc;
};

/// The *CASE definitions of the deck in deck order; errors (a repeated CASEID, a bad card, a
/// *PARAMETER inside a subcase) go to `diags`.
std::vector<Case> read_cases(const Deck& deck, core::Diagnostics& diags);

/// Keeps the keywords of the main model and of the subcases `c` reads.
void keep_case(Deck& deck, const Case& c);

/// Keeps only the main model (the keywords of no subcase).
void keep_main_model(Deck& deck);

}  // namespace mcdyna::deck
