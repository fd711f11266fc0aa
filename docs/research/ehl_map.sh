# usage: [TOL=1e-9|0] ehl_map.sh nodes (0 = the default, grid by the error target) — the issue's map (M 1–1000, L 0–25 by 2.5) with ./drv from ehl_driver.cpp; failures listed, WU per point in map_<nodes>.log
# usage: map.sh nodes(0=adaptive) -> summary of failures over the map
ok=0; fail=0; fl=""
for M in 1 2 5 10 20 50 100 200 500 1000; do for L in 0 2.5 5 7.5 10 12.5 15 17.5 20 22.5 25; do
  out=$(timeout ${TMO:-30} ./drv $M $L $1 0 0.8 0.4 1 ${TOL:-1e-9} 2>&1)
  if echo "$out" | grep -q "exceeds 40"; then continue; fi
  if echo "$out" | grep -q "^M.*: converged"; then ok=$((ok+1)); wu=$(echo "$out" | grep -o 'WU [0-9.]*' | head -1); echo "$M $L OK $wu" >> map_$1.log; else fail=$((fail+1)); fl="$fl ($M,$L)"; echo "$M $L FAIL" >> map_$1.log; fi
done; done
echo "nodes $1: ok $ok fail $fail:$fl"
