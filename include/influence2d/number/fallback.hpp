// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The filter of the exact modes: a computation in a fast number type whose
/// signs may be in doubt, and the same computation in an exact type when one
/// is.

#include "influence2d/number/certified.hpp"

namespace influence2d {

/// Runs `fast`; if it raises uncertain_sign (a sign of a filtered number type
/// that its error bound cannot settle) or one of the exception types
/// Uncertain... (for number types whose comparisons raise their own), runs
/// `exact` and returns its value instead. What `fast` did before it raised is
/// discarded: it must leave no state that `exact` or a later call relies on.
/// `fast` runs with its doubts raised (doubt_raising), whether or not a
/// doubt_noting lives outside the call, which would otherwise take them as
/// 0 and keep fast's answer.
template <class... Uncertain>
struct fallback;

/// fallback with uncertain_sign alone.
template <>
struct fallback<> {
    /// fast(), or exact() when fast() raises uncertain_sign.
    template <class Fast, class Exact>
    static auto run(Fast&& fast, Exact&& exact) {
        try {
            const doubt_raising raised;
            return fast();
        } catch (const uncertain_sign&) {
            return exact();
        }
    }
};

/// fallback with uncertain_sign, First and Rest....
template <class First, class... Rest>
struct fallback<First, Rest...> {
    /// fast(), or exact() when fast() raises uncertain_sign, First or one of Rest....
    template <class Fast, class Exact>
    static auto run(Fast&& fast, Exact&& exact) {
        try {
            return fallback<Rest...>::run(fast, exact);
        } catch (const First&) {
            return exact();
        }
    }
};

/// fallback<>::run for a fast computation that may run on through its doubts
/// (doubt_noting's conditions: it ends whatever signs it is given and keeps
/// no state): run with its doubts noted instead of raised, its answer kept
/// when none was; else, or when it raised uncertain_sign all the same,
/// `exact`'s. A doubt then costs no unwinding of the stack.
struct noted_fallback {
    /// fast(), or exact() when fast() noted or raised a doubt.
    template <class Fast, class Exact>
    static auto run(Fast&& fast, Exact&& exact) {
        try {
            const doubt_noting doubts;
            auto answer = fast();
            if (!doubts.noted()) return answer;
        } catch (const uncertain_sign&) {}
        return exact();
    }
};

}  // namespace influence2d
