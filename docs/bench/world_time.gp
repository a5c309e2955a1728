set terminal pngcairo size 2000,900 font ',9'
set output 'docs/bench/world_time.png'
set multiplot layout 2,4
set logscale xy
set key top left
set xlabel 'bodies'
set ylabel 'time per step (us)'
set title 'falling'
plot 'docs/bench/plot_0.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_1.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_2.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_3.dat' with linespoints title 'certified', 'docs/bench/plot_4.dat' with linespoints title 'double', 'docs/bench/plot_5.dat' with linespoints title 'double, all cores', 'docs/bench/plot_6.dat' with linespoints title 'double, no witness'
set title 'convex'
plot 'docs/bench/plot_7.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_8.dat' with linespoints title 'Box2D dynamic tree', 'docs/bench/plot_9.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_10.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_11.dat' with linespoints title 'certified', 'docs/bench/plot_12.dat' with linespoints title 'double', 'docs/bench/plot_13.dat' with linespoints title 'double, all cores', 'docs/bench/plot_14.dat' with linespoints title 'double, no witness'
set title 'parcels'
plot 'docs/bench/plot_15.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_16.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_17.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_18.dat' with linespoints title 'certified', 'docs/bench/plot_19.dat' with linespoints title 'double', 'docs/bench/plot_20.dat' with linespoints title 'double, all cores', 'docs/bench/plot_21.dat' with linespoints title 'double, no witness'
set title 'random'
plot 'docs/bench/plot_22.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_23.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_24.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_25.dat' with linespoints title 'certified', 'docs/bench/plot_26.dat' with linespoints title 'double', 'docs/bench/plot_27.dat' with linespoints title 'double, all cores', 'docs/bench/plot_28.dat' with linespoints title 'double, no witness'
set title 'mixed'
plot 'docs/bench/plot_29.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_30.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_31.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_32.dat' with linespoints title 'certified', 'docs/bench/plot_33.dat' with linespoints title 'double', 'docs/bench/plot_34.dat' with linespoints title 'double, all cores', 'docs/bench/plot_35.dat' with linespoints title 'double, no witness'
set title 'far'
plot 'docs/bench/plot_36.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_37.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_38.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_39.dat' with linespoints title 'certified', 'docs/bench/plot_40.dat' with linespoints title 'double', 'docs/bench/plot_41.dat' with linespoints title 'double, all cores', 'docs/bench/plot_42.dat' with linespoints title 'double, no witness'
set title 'trajectories'
plot 'docs/bench/plot_43.dat' with linespoints title 'Boost.Geometry rtree', 'docs/bench/plot_44.dat' with linespoints title 'GEOS STRtree + prepared', 'docs/bench/plot_45.dat' with linespoints title 'all pairs, one-shot', 'docs/bench/plot_46.dat' with linespoints title 'certified', 'docs/bench/plot_47.dat' with linespoints title 'double', 'docs/bench/plot_48.dat' with linespoints title 'double, all cores', 'docs/bench/plot_49.dat' with linespoints title 'double, no witness'
unset multiplot
