#include "solver/integer_program.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

using namespace fcql;
using Sense = IntegerProgram::Sense;

TEST(IntegerProgram, SolvesASetPackingExactly) {
  // Maximise 3a + 2b + 2c with a+b <= 1, a+c <= 1: optimum b = c = 1 (value 4).
  IntegerProgram ip;
  ip.setMaximize(true);
  int a = ip.addBinary(3), b = ip.addBinary(2), c = ip.addBinary(2);
  ip.addConstraint({{a, 1}, {b, 1}}, Sense::LessEqual, 1);
  ip.addConstraint({{a, 1}, {c, 1}}, Sense::LessEqual, 1);
  auto r = ip.solve(5);
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal);
  EXPECT_NEAR(r.values[a], 0, 1e-9);
  EXPECT_NEAR(r.values[b], 1, 1e-9);
  EXPECT_NEAR(r.values[c], 1, 1e-9);
  EXPECT_NEAR(r.objective, 4, 1e-9);
}

TEST(IntegerProgram, IntegerVariablesAndEqualities) {
  // Minimise |x - 2.6| with x integer: t >= x - 2.6, t >= 2.6 - x.
  IntegerProgram ip;
  int x = ip.addVariable(1, 100, true);
  int t = ip.addVariable(0, 1e9, false, 1);
  ip.addConstraint({{t, 1}, {x, -1}}, Sense::GreaterEqual, -2.6);
  ip.addConstraint({{t, 1}, {x, 1}}, Sense::GreaterEqual, 2.6);
  auto r = ip.solve(5);
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal);
  EXPECT_NEAR(r.values[x], 3, 1e-9);
  int y = ip.addVariable(0, 10, true);
  ip.addConstraint({{x, 1}, {y, -1}}, Sense::Equal, 0);
  ip.addConstraint({{y, 1}}, Sense::GreaterEqual, 5);
  r = ip.solve(5);
  ASSERT_EQ(r.status, IntegerProgram::Status::Optimal);
  EXPECT_NEAR(r.values[x], 5, 1e-9);
}

TEST(IntegerProgram, InfeasibleAndUnboundedAreReported) {
  IntegerProgram ip;
  int x = ip.addBinary(1);
  ip.addConstraint({{x, 1}}, Sense::GreaterEqual, 2);
  auto r = ip.solve(5);
  EXPECT_EQ(r.status, IntegerProgram::Status::Infeasible);
  EXPECT_FALSE(r.hasSolution());
  EXPECT_NE(r.message.find("infeasible"), std::string::npos);

  IntegerProgram un;
  un.setMaximize(true);
  un.addVariable(0, std::numeric_limits<double>::infinity(), false, 1);
  auto u = un.solve(5);
  EXPECT_EQ(u.status, IntegerProgram::Status::Unbounded);
  EXPECT_FALSE(u.hasSolution());
  EXPECT_THROW(ip.addVariable(2, 1, false), std::invalid_argument);
  EXPECT_THROW(ip.addConstraint({{99, 1}}, Sense::Equal, 0), std::out_of_range);
}

TEST(IntegerProgram, TimeLimitIsHonoured) {
  // A hard set-packing instance (odd cycles with tiny weight differences); whatever lp_solve
  // achieves, it must return near the 1 s limit with a feasible answer or a clear failure.
  IntegerProgram ip;
  ip.setMaximize(true);
  const int n = 400;
  for (int i = 0; i < n; ++i) ip.addBinary(1.0 + 1e-3 * ((i * 7919) % 101));
  for (int i = 0; i < n; ++i)
    for (int d : {1, 7, 31, 97}) ip.addConstraint({{i, 1}, {(i + d) % n, 1}}, Sense::LessEqual, 1);
  auto start = std::chrono::steady_clock::now();
  auto r = ip.solve(1);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 4.0);
  if (r.status != IntegerProgram::Status::Optimal) EXPECT_TRUE(r.timeLimitReached) << "a safety stop is flagged";
  if (r.hasSolution()) {
    for (int i = 0; i < n; ++i)
      for (int d : {1, 7, 31, 97}) EXPECT_LE(r.values[i] + r.values[(i + d) % n], 1.0 + 1e-9);
  } else {
    EXPECT_FALSE(r.message.empty());
  }
}

TEST(IntegerProgram, RoundingTheRelaxationGivesAFeasibleIntegerSolution) {
  // min Σ |x_i − ideal_i| with x integer in [1, 50] and x0 + x1 = x2, x2 + x3 = x4 + x5: the
  // ideals break both equalities, so the relaxation moves some values off them, fractional
  // ones among them. The rounded solution must be integral, satisfy both equalities, and cost
  // no more than half a unit per variable (3); rounding each ideal on its own would cost 2.55
  // but break the second equality (9 + 3 ≠ 4 + 7).
  const std::vector<double> ideal = {3.4, 5.5, 8.6, 2.5, 4.45, 6.7};
  IntegerProgram ip;
  std::vector<int> x;
  for (double v : ideal) {
    const int xi = ip.addVariable(1, 50, true);
    const int t = ip.addVariable(0, 1e9, false, 1);
    ip.addConstraint({{t, 1}, {xi, -1}}, Sense::GreaterEqual, -v);
    ip.addConstraint({{t, 1}, {xi, 1}}, Sense::GreaterEqual, v);
    x.push_back(xi);
  }
  ip.addConstraint({{x[0], 1}, {x[1], 1}, {x[2], -1}}, Sense::Equal, 0);
  ip.addConstraint({{x[2], 1}, {x[3], 1}, {x[4], -1}, {x[5], -1}}, Sense::Equal, 0);
  const auto r = ip.solveByRounding(5);
  ASSERT_TRUE(r.hasSolution()) << r.message;
  EXPECT_EQ(r.status, IntegerProgram::Status::TimeLimit) << "not proven optimal";
  double cost = 0;
  for (std::size_t i = 0; i < ideal.size(); ++i) {
    EXPECT_EQ(r.values[x[i]], std::round(r.values[x[i]]));
    cost += std::abs(r.values[x[i]] - ideal[i]);
  }
  EXPECT_EQ(r.values[x[0]] + r.values[x[1]], r.values[x[2]]);
  EXPECT_EQ(r.values[x[2]] + r.values[x[3]], r.values[x[4]] + r.values[x[5]]);
  EXPECT_LE(cost, 3.0 + 1e-9);
  EXPECT_NEAR(r.objective, cost, 1e-6);

  // An equality no integers satisfy (2y = 3 with y in [0, 5]) is reported, not rounded away.
  IntegerProgram odd;
  const int y = odd.addVariable(0, 5, true, 1);
  odd.addConstraint({{y, 2}}, Sense::Equal, 3);
  const auto bad = odd.solveByRounding(5);
  EXPECT_FALSE(bad.hasSolution());
  EXPECT_EQ(bad.status, IntegerProgram::Status::Infeasible);
  EXPECT_FALSE(bad.message.empty());

  // Bounds that hold no integer, and an unbounded program, are reported as such.
  IntegerProgram gap;
  gap.addVariable(0.3, 0.7, true, 1);
  EXPECT_EQ(gap.solveByRounding(5).status, IntegerProgram::Status::Infeasible);
  IntegerProgram unbounded;
  unbounded.setMaximize(true);
  unbounded.addVariable(0, std::numeric_limits<double>::infinity(), true, 1);
  const auto u = unbounded.solveByRounding(5);
  EXPECT_EQ(u.status, IntegerProgram::Status::Unbounded);
  EXPECT_FALSE(u.hasSolution());

  // A relaxation that is integral at once is the program's optimum.
  IntegerProgram integral;
  const int z = integral.addVariable(2, 9, true, 1);
  const auto i = integral.solveByRounding(5);
  EXPECT_EQ(i.status, IntegerProgram::Status::Optimal);
  EXPECT_EQ(i.values[z], 2);
}

TEST(IntegerProgram, StopsWhenTheBestSolutionStopsImproving) {
  // Jeroslow's program: max Σ w_j x_j with 2 Σ x_j ≤ 41. Any 20 items are a solution, found at
  // once, but the LP bound of nearly every node stays above the best solution, so branch and
  // bound cannot prove optimality in any reasonable time: only the stall limit stops it early.
  const int n = 41;
  IntegerProgram ip;
  ip.setMaximize(true);
  std::vector<std::pair<int, double>> terms;
  for (int j = 0; j < n; ++j) terms.push_back({ip.addBinary(1 + 0.001 * j), 2.0});
  ip.addConstraint(terms, Sense::LessEqual, n);
  ip.setStallNodes(2000);
  const auto r = ip.solve(120);
  ASSERT_EQ(r.status, IntegerProgram::Status::Stalled) << r.message;
  ASSERT_TRUE(r.hasSolution());
  EXPECT_FALSE(r.timeLimitReached);
  EXPECT_GE(r.nodes, 2000) << "the stall is counted in nodes";
  EXPECT_LT(r.seconds, 30) << "stopped by the stall limit, long before the time limit";
  double items = 0, value = 0;
  for (int j = 0; j < n; ++j) {
    EXPECT_TRUE(r.values[j] == 0 || r.values[j] == 1);
    items += r.values[j];
    value += (1 + 0.001 * j) * r.values[j];
  }
  EXPECT_EQ(items, 20) << "a best solution takes as many items as fit";
  EXPECT_NEAR(r.objective, value, 1e-9);

  // Work, not time: with both cores kept busy by two spinning threads, the same program stops
  // at the same node with the same solution.
  std::atomic<bool> busy{true};
  std::vector<std::thread> hogs;
  for (int t = 0; t < 2; ++t)
    hogs.emplace_back([&busy] {
      volatile double x = 1;
      while (busy.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
    });
  const auto again = ip.solve(120);
  busy = false;
  for (auto& h : hogs) h.join();
  EXPECT_EQ(again.status, r.status);
  EXPECT_EQ(again.nodes, r.nodes);
  EXPECT_EQ(again.values, r.values);

  // A node budget stops it too, keeping the best solution (status WorkLimit).
  IntegerProgram budget = ip;
  budget.setStallNodes(0);
  budget.setNodeLimit(300);
  const auto b = budget.solve(120);
  ASSERT_EQ(b.status, IntegerProgram::Status::WorkLimit) << b.message;
  EXPECT_TRUE(b.hasSolution());
  EXPECT_GE(b.nodes, 300);
  EXPECT_LT(b.nodes, 400) << "stopped soon after the budget";
  EXPECT_EQ(budget.solve(120).values, b.values);
}

TEST(IntegerProgram, BranchingDownFirstFindsTheSameOptimum) {
  // Side-length-like program: integer counts n_i, each with the cost
  // max(n − ideal, 3·(ideal − n)) (rounding down costs three times more), tied by equalities
  // n_i + n_{i+1} = n_{i+2} that the ideals do not satisfy exactly. The branching direction
  // must not change what is optimal, only the order branch and bound explores it in (and
  // so how many nodes it takes).
  auto build = [](bool down) {
    IntegerProgram ip;
    std::vector<int> n;
    const int m = 24;
    for (int i = 0; i < m; ++i) {
      const double ideal = 1.3 + 0.37 * ((i * 7) % 11);
      n.push_back(ip.addVariable(1, 40, true));
      const int t = ip.addVariable(0, 1e9, false, 1);
      ip.addConstraint({{t, 1}, {n.back(), -1}}, Sense::GreaterEqual, -ideal);
      ip.addConstraint({{t, 1}, {n.back(), 3}}, Sense::GreaterEqual, 3 * ideal);
    }
    for (int i = 0; i + 2 < m; i += 3) ip.addConstraint({{n[i], 1}, {n[i + 1], 1}, {n[i + 2], -1}}, Sense::Equal, 0);
    ip.setBranchDownFirst(down);
    return ip;
  };
  const auto up = build(false).solve(10), down = build(true).solve(10);
  ASSERT_EQ(up.status, IntegerProgram::Status::Optimal);
  ASSERT_EQ(down.status, IntegerProgram::Status::Optimal);
  EXPECT_NEAR(down.objective, up.objective, 1e-6);
  EXPECT_NE(down.nodes, up.nodes);  // the option does reach lp_solve: the search differs
}
