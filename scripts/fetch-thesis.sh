#!/usr/bin/env bash
# Fetch a sample of the 2016 CPLEX thesis's instances (github.com/d-krupke/mt, pinned to one
# commit) and its results table (instances/thesis/results/fc.csv) into instances/thesis/, checking each file's SHA-256.
# The files are not committed here because the repository states no licence.
#
#   scripts/fetch-thesis.sh            # then: mowmill bench --config experiments/thesis-sample.toml ...
set -euo pipefail
cd "$(dirname "$0")/../instances/thesis"
base=https://raw.githubusercontent.com/d-krupke/mt/58c842c6f5bf4f5b073883ee0ecff268145c0863/experiments
while read -r sum name; do
  case "$name" in
    results/fc.csv) url="$base/results/gridgraph/fc.csv"; mkdir -p results ;;
    *) url="$base/instances/gridgraph/fc/$name" ;;
  esac
  if [ ! -f "$name" ]; then
    curl -fsSL --retry 3 -o "$name.part" "$url"
    mv "$name.part" "$name"
  fi
  echo "$sum  $name" | sha256sum --check --quiet || { echo "$name: checksum differs from the pinned file" >&2; exit 1; }
done <<'SUMS'
c72a6552fc9abea4e92ec9c5ae999c5fa72d0c08e6bbcf7a4fda9efff804aae0  fc_1000_dense_0.gg
54c179f162f3ce5fc6ebbf36a25ad7a42757c6d5048d15775edc6ef238202b84  fc_1000_dense_1.gg
eebfc0212967fc83a6c52f4517b7cb163551acc72a76b5b1248319888e6de16e  fc_1000_sparse_0.gg
92ca96fed86e5cf8049f0eeeae2312b82bc771e1a60e5b663d2c48122434badc  fc_1000_sparse_1.gg
4a40bb4e316cc6da7466ef9753bf699451d123a3474bfb5494de7916abb4df53  fc_100_dense_0.gg
e814e529d15bce435537c00b700592c12e33b61668f042112bf6324f936fa258  fc_100_sparse_0.gg
34e928e0b10d6761983c69ff0782ca01f2a9fe99a920809b2297f4ae962a6c12  fc_1500_dense_0.gg
339bf598be360ac7dae1db30c952b9b8751e8891d00d04b65b037c0ac437fffd  fc_1500_dense_1.gg
98595eefb49e261ce8090211f680cd573e31132a6304738c71657383ab8ff8be  fc_1500_sparse_0.gg
e6ccc4b7e4e743a7b80fddf73d11f6b5cca79cec673cec7d5a395b89caea8603  fc_1500_sparse_1.gg
0f9401b36a8b88fba2c7f11ca0d7f6246bb14f982e378d4fcbe1e89558ca9f35  fc_2000_dense_0.gg
8025861aa657db429ed847ead8ca31ba7cb2f0e8cfd019b46bd3c6bcc3daaabe  fc_2000_dense_1.gg
0dcf1aec2671e029ccbd2bd5c1bd92b2f7662b59b7a03e6dfdba54e9d7aea437  fc_2000_sparse_0.gg
27eba55507772cf82a36d14c51c65c94b874bf71e0f814da5216096a128e89c9  fc_2000_sparse_1.gg
19dabf767061cfdcc49f1231fe561f4d9d6623e5759f59b6ea244076c7894eee  fc_2500_dense_0.gg
2039615f692d174c5efe5488f962b304515012f2c72b0bcf17b3027d5e76cbf3  fc_2500_dense_1.gg
0e61be6d9a54054b1660eb31ab7b8afa6f783b6f18aed6a04b73c68748073292  fc_2500_sparse_0.gg
d3ff1f6e2e5080d1d0ba2370870cda9b6affe8ed5ed747d68361e0389fb7fa78  fc_2500_sparse_1.gg
7c952c9e21c3a50b8efad7defc505aff8e5f731196ab6db5322360b5debf9e60  fc_2900_dense_0.gg
ee364435ce9f78618f0262d908b53440b4cf75c4caa99b7367cb70b49b7b4f5d  fc_2900_dense_1.gg
005071528201299863504f9e02c57bdd347d7bb1f8663a1ea8fbfa0543614656  fc_2900_sparse_0.gg
71d053a527ace066345aa86d5299d2238761f4fe72945ca0f289ad898786a80d  fc_2900_sparse_1.gg
b189caf1dda7c04fc36f5b46a3a6e644b0711f5619d2b7068063ac5364cbff94  fc_500_dense_0.gg
9fc4293be83aadff79f67572544824ed51b2b31361aafda535a841f47341838e  fc_500_sparse_0.gg
5cc5b239925087695015f1d71d4999cfa0863fc15fe77cf07dc6f5f1275de91c  results/fc.csv
SUMS
echo "instances/thesis: $(ls *.gg | wc -l) instances and results/fc.csv"
