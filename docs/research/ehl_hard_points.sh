# usage: [PTS="M L ..."] ehl_hard_points.sh "N list" [omega_gs omega_j xi] — the hard points at the error stop, with ./drv built from ehl_driver.cpp:
#   g++ -std=c++20 -O2 -I<tree>/solvers -I/usr/include/eigen3 ehl_driver.cpp <tree>/build/default/solvers/libgearbench_solvers.a <tree>/build/default/solvers/libgearbench_model.a -lfftw3 -lgsl -lgslcblas -lfmt -o drv
for pt in ${PTS:-"10 17.5" "20 10" "5 17.5" "2 22.5" "20 20" "100 10" "50 12.5" "10 0" "1 10" "20 5" "1 25" "200 5"}; do for n in $1; do
  out=$(timeout ${TMO:-60} ./drv $pt $n 0 ${2:-0.8} ${3:-0.4} ${4:-1} 0 2>&1)
  st=$(echo "$out" | grep -q "^M.*: converged" && echo OK || (echo "$out" | grep -q "exceeds 40" && echo RANGE || echo FAIL))
  cyc=$(echo "$out" | grep -o "after [0-9]* cycles" | head -1)
  echo "$pt $n $st $cyc $(echo "$out" | grep -o 'Hc [0-9.]* Hmin [0-9.]*') $(echo "$out" | grep -o 'WU [0-9.]*' | head -1)"
done; done
