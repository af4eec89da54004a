import csv, pathlib, sys
here = pathlib.Path(__file__).resolve().parent
def load(v):
    return {(r['scene'],r['resolution'],r['fraction']):r for r in csv.DictReader(open(f'{here}/pareto.{v}.csv'))}
vs=sys.argv[1:]
data={v:load(v) for v in ['base']+vs}
cols={'cube':['E_error','nu_error'],'plastic':['yield_error','tangent_error'],'wave':['speed_error','energy_error','amplitude_loss']}
for k,b in data['base'].items():
    for c in cols[k[0]]:
        line=f"{k[0]:8s} {k[1]:>3s} {k[2]:4s} {c:15s} base {float(b[c]):+.6e}"
        for v in vs:
            if k in data[v]:
                x=float(data[v][k][c]); line+=f" | {v} {x:+.6e} (d {x-float(b[c]):+.2e})"
        print(line)
