#pragma once
// Exact signs of sums of products of doubles, by floating-point expansions
// (error-free transformations: two_sum and an fma-based two_product).
// Used where preprocessing must decide a sign exactly on input doubles:
// ring orientation, and the orientation predicate on unposed input points.

#include <cmath>
#include <vector>

namespace influence2d::expansion {

/// a + b = s + e exactly (Knuth's two-sum).
inline void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a;
    const double av = s - bv;
    e = (a - av) + (b - bv);
}

/// a * b = p + e exactly (fma computes the rounding error of the product).
inline void two_product(double a, double b, double& p, double& e) {
    p = a * b;
    e = std::fma(a, b, -p);
}

/// An exact sum of doubles kept as a nonoverlapping expansion, smallest
/// component first (Shewchuk's grow-expansion with zero elimination).
class accumulator {
public:
    void add(double x) {
        double q = x;
        std::size_t k = 0;
        for (double h : parts_) {
            double s, e;
            two_sum(q, h, s, e);
            q = s;
            if (e != 0) parts_[k++] = e;
        }
        parts_.resize(k);
        if (q != 0) parts_.push_back(q);
    }

    /// Adds a * b exactly.
    void add_product(double a, double b) {
        double p, e;
        two_product(a, b, p, e);
        add(e);
        add(p);
    }

    /// The sign of the exact sum: that of its largest component.
    int sign() const {
        if (parts_.empty()) return 0;
        return parts_.back() > 0 ? 1 : -1;
    }

private:
    std::vector<double> parts_;
};

/// The exact sign of the orientation determinant of three points with double
/// coordinates: [a b c] = bx cy - bx ay - ax cy - by cx + by ax + ay cx, each
/// product kept exactly.
inline int orientation_sign(double ax, double ay, double bx, double by, double cx, double cy) {
    accumulator acc;
    acc.add_product(bx, cy);
    acc.add_product(-bx, ay);
    acc.add_product(-ax, cy);
    acc.add_product(-by, cx);
    acc.add_product(by, ax);
    acc.add_product(ay, cx);
    return acc.sign();
}

}  // namespace influence2d::expansion
