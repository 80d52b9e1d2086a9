# Reference values for the new statistics: SciPy 1.x / statsmodels / mpmath / brute force, run once by hand.
import itertools, math
import numpy as np
from scipy import stats
from mpmath import mp, mpf, erfc, sqrt
from statsmodels.stats.multitest import multipletests
from statsmodels.stats.power import TTestPower
mp.dps = 50
print("== Wilcoxon normal tail: 51 positive distinct differences")
n=51; w=n*(n+1)/2; E=n*(n+1)/4; V=n*(n+1)*(2*n+1)/24
z=(mpf(w)-mpf(E)-mpf('0.5'))/sqrt(mpf(V))
print("z", z, "p", mp.nstr(erfc(z/sqrt(2)), 20))
print("== Holm (statsmodels multipletests method='holm')")
for p in ([0.01,0.04,0.03], [0.2,0.001,0.04,0.04,0.5,0.011], [1.0,1.0], [0.0078125,0.0078125,0.0078125]):
    print(p, list(multipletests(p, method='holm')[1]))
print("== Friedman (scipy.stats.friedmanchisquare) + Iman-Davenport (scipy.stats.f.sf)")
def fr(data):
    data=np.array(data,float); n,k=data.shape
    chi,p=stats.friedmanchisquare(*[data[:,j] for j in range(k)])
    F=(n-1)*chi/(n*(k-1)-chi); pf=stats.f.sf(F,k-1,(k-1)*(n-1))
    ranks=np.mean([stats.rankdata(r) for r in data],axis=0)
    print(repr(chi), repr(p), repr(F), repr(pf), list(ranks))
fr([[0.10,0.20,0.30],[0.12,0.25,0.22],[0.11,0.21,0.35],[0.15,0.15,0.40],[0.09,0.30,0.29],[0.13,0.13,0.13],[0.20,0.18,0.50]])
fr([[1,2,3,4],[2,1,3,4],[1,3,2,4],[1,2,4,3],[1,2,3,4],[2,1,4,3],[1,2,3,4],[1,3,2,4],[1,2,3,4],[3,1,2,4]])
print("== Hodges-Lehmann: brute-force signed-rank distribution")
def hl(d, level):
    d=np.array(d,float); n=len(d)
    walsh=sorted((d[i]+d[j])/2 for i in range(n) for j in range(i,n)); M=len(walsh)
    est=np.median(walsh)
    # P(T <= c) by enumerating all 2^n sign patterns of ranks 1..n
    counts={}
    for signs in itertools.product([0,1],repeat=n):
        t=sum(r+1 for r,s in enumerate(signs) if s); counts[t]=counts.get(t,0)+1
    cdf=np.cumsum([counts.get(t,0) for t in range(M+1)])/2**n
    alpha=1-level
    c=max([t for t in range(M+1) if cdf[t]<=alpha/2], default=-1)
    k=max(1,c+1)
    print(repr(est), repr(walsh[k-1]), repr(walsh[M-k]), repr(1-2*cdf[k-1]))
hl([0.3,-0.1,0.25,0.0,0.4,0.25,0.12,-0.05,0.33,0.18], 0.95)
hl([0.3,-0.1,0.25,0.0,0.4,0.25,0.12,-0.05,0.33,0.18], 0.9)
hl([0.5], 0.95)
hl([0.5,-0.2], 0.95)
hl([1.0,2.0,3.0,4.0,5.0,6.0], 0.95)
print("== HL asymptotic, n = 60: d_i = sin(i) + 0.3")
d=[math.sin(i)+0.3 for i in range(1,61)]; n=60
walsh=sorted((d[i]+d[j])/2 for i in range(n) for j in range(i,n)); M=len(walsh)
k=max(1, int(np.floor(M/2 - stats.norm.isf(0.025000000000000022)*math.sqrt(n*(n+1)*(2*n+1)/24) + 0.5)))
print(repr(np.median(walsh)), k, repr(walsh[k-1]), repr(walsh[M-k]))
print("== Planning (scipy.stats.t.isf) and statsmodels TTestPower exact n")
for sd,n,level,power in ((1.0,10,0.95,0.8),(0.0123,8,0.95,0.8),(2.5,30,0.9,0.9),(0.02,2,0.95,0.8)):
    q=(1-level)/2
    mdd=(stats.t.isf(q,n-1)+stats.t.isf(1-power,n-1))*sd/math.sqrt(n)
    print(sd,n,level,power,repr(mdd))
for sd,delta,level,power in ((1.0,0.5,0.95,0.8),(0.0123,0.01,0.95,0.8),(2.5,1.0,0.9,0.9),(1.0,3.0,0.95,0.8)):
    q=(1-level)/2
    nn=next(m for m in range(2,10**6) if (stats.t.isf(q,m-1)+stats.t.isf(1-power,m-1))*sd/math.sqrt(m)<=delta)
    exact=TTestPower().solve_power(effect_size=delta/sd, alpha=1-level, power=power, alternative='two-sided')
    print(sd,delta,level,power,nn, "statsmodels exact (noncentral t):", exact)
print("== Variance components: ANOVA estimator by formula; balanced case also statsmodels MixedLM REML")
import statsmodels.formula.api as smf, pandas as pd
rng=np.random.default_rng(3)
seqfx=[0.10,0.30,0.05,0.22,0.41,0.18,0.27,0.09]
bal=[[round(seqfx[s]+0.02*math.sin(7*s+3*k),6) for k in range(5)] for s in range(8)]
print("balanced data", bal)
def anova(groups):
    groups=[np.array(g,float) for g in groups if len(g)>0]; g=len(groups); N=sum(len(x) for x in groups)
    grand=np.concatenate(groups).mean()
    msb=sum(len(x)*(x.mean()-grand)**2 for x in groups)/(g-1)
    msw=sum(((x-x.mean())**2).sum() for x in groups)/(N-g)
    n0=(N-sum(len(x)**2 for x in groups)/N)/(g-1)
    seq=max(0,(msb-msw)/n0)
    print(repr(math.sqrt(seq)), repr(math.sqrt(msw)), repr(n0), repr(seq/(seq+msw)))
anova(bal)
df=pd.DataFrame([(s,v) for s in range(8) for v in bal[s]],columns=['s','y'])
m=smf.mixedlm("y ~ 1", df, groups=df["s"]).fit(reml=True)
print("MixedLM REML sd_seq", math.sqrt(float(m.cov_re.iloc[0,0])), "sd_seed", math.sqrt(m.scale))
unbal=[[1.0,1.2,0.9],[2.0,2.1],[0.5,0.7,0.6,0.4],[1.5],[]]
anova(unbal)
print("== Korn-Graubard clustered CP (scipy beta.ppf / beta.isf / t.isf)")
def kg(f,nr,level):
    f=np.array(f); nr=np.array(nr); keep=nr>0; f=f[keep]; nr=nr[keep]
    g=len(nr); F=f.sum(); N=nr.sum(); p=F/N
    v=g/(g-1)*((f-p*nr)**2).sum()/N**2
    ns=min(N,p*(1-p)/v) if v>0 else N
    q=(1-level)/2
    ndf=ns*(stats.t.isf(q,N-1)/stats.t.isf(q,g-1))**2
    x=p*ndf
    lo=0.0 if F==0 else stats.beta.ppf(q,x,ndf-x+1)
    hi=1.0 if F==N else stats.beta.isf(q,x+1,ndf-x)
    print(f.tolist(), nr.tolist(), level, repr(N/ns), repr(ndf), repr(lo), repr(hi))
kg([0,0,0,0,0,1,0,0],[5]*8,0.95)
kg([1,0],[10,10],0.95)
kg([0]*8,[5]*8,0.95)
kg([5]*8,[5]*8,0.95)
kg([3,0,1,5,0,0,2,0,0,4],[5,5,5,5,4,5,5,5,5,5],0.9)
kg([2,2,2,2],[4,4,4,4],0.95)
