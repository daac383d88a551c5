"""The main job's fits against the reference table: the ten slowest fits, and every fit whose
fitting-metric error exceeds 1.005 x the reference (bench/main_job.sh calls it).

usage: python3 bench/main_job_compare.py SUMMARY.csv REFERENCE.csv
"""
import csv
import sys


def main(summary_path, reference_path):
    with open(summary_path, newline="") as f:
        fits = list(csv.DictReader(f))
    with open(reference_path, newline="") as f:
        reference = {(r["material"], r["model"]): float(r["ngan"]) for r in csv.DictReader(f)}

    fitted = [r for r in fits if r["status"] in ("fitted", "resumed")]
    print(f"fits: {len(fits)}, fitted {len(fitted)}, failed {len(fits) - len(fitted)}; "
          f"sum of fit seconds {sum(float(r['seconds']) for r in fitted):.1f}")
    print("ten slowest fits (s):")
    for r in sorted(fitted, key=lambda r: -float(r["seconds"]))[:10]:
        print(f"  {float(r['seconds']):8.1f}  {r['material']} {r['model']}")

    compared, worse, ratios = 0, [], []
    for r in fitted:
        key = (r["material"], r["model"])
        if key not in reference or not r[r["fit_metric"]]:
            continue
        compared += 1
        ratio = float(r[r["fit_metric"]]) / reference[key]
        ratios.append(ratio)
        if ratio > 1.005:
            worse.append((ratio, key))
    print(f"error vs reference: {compared} fits compared, {len(worse)} worse than 1.005x"
          + (f", ratio min {min(ratios):.4f} max {max(ratios):.4f}" if ratios else ""))
    for ratio, (material, model) in sorted(worse, reverse=True):
        print(f"  {ratio:.4f}x  {material} {model}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
