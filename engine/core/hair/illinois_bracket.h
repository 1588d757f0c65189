#pragma once
// Contract: the bracket of a regula falsi root search, Illinois variant: the two ends (a parameter or a
// point, type P) have values of opposite sign; narrow(p, f) replaces the end whose value has f's sign,
// and an end kept twice in a row has its value halved, so a curved function does not stall one end.
// Used by the level-set mesher (zeros on grid edges) and the head's scalp rays. Header only, no state
// beyond the bracket.
namespace hp {
template <typename P>
struct IllinoisBracket {
  P a{}, b{};
  float fa = 0.0f, fb = 0.0f;
  int kept = 0;  // -n: b kept n times in a row (a moved), +n: a kept

  void narrow(const P& p, float fp) {
    if ((fp < 0.0f) == (fa < 0.0f)) {
      a = p, fa = fp, kept = kept < 0 ? kept - 1 : -1;
      if (kept <= -2) fb *= 0.5f;
    } else {
      b = p, fb = fp, kept = kept > 0 ? kept + 1 : 1;
      if (kept >= 2) fa *= 0.5f;
    }
  }
};
}  // namespace hp
