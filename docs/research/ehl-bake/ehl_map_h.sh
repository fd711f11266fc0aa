# ehl_map.sh with H_c, H_min and cycles recorded per point (map_h_<nodes>.log)
ok=0; fail=0; fl=""
for M in 1 2 5 10 20 50 100 200 500 1000; do for L in 0 2.5 5 7.5 10 12.5 15 17.5 20 22.5 25; do
  out=$(timeout ${TMO:-30} ./drv $M $L $1 0 0.8 0.4 1 ${TOL:-1e-9} 2>&1)
  if echo "$out" | grep -q "exceeds 40"; then continue; fi
  h=$(echo "$out" | grep -o 'Hc [0-9.]* Hmin [0-9.]*'); wu=$(echo "$out" | grep -o 'WU [0-9.]*' | head -1); cyc=$(echo "$out" | grep -o "after [0-9]* cycles" | head -1)
  if echo "$out" | grep -q "^M.*: converged"; then ok=$((ok+1)); echo "$M $L OK $wu $h $cyc" >> map_h_$1.log; else fail=$((fail+1)); fl="$fl ($M,$L)"; echo "$M $L FAIL $h" >> map_h_$1.log; fi
done; done
echo "nodes $1: ok $ok fail $fail:$fl"
