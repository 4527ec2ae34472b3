#!/usr/bin/env python3
"""Independent reference for the plastic hinges of frames (issue 25, docs/manual.md, "Inelastic buildings: plastic hinges of frames").

A one-bay, one-storey portal (fixed base, h = 3 m, L = 6 m, E = 3e7 kPa, columns A = 0.16 m^2,
I = 3.75e-4 m^4, My = 45 kN m; beam A = 0.15 m^2, I = 1e-3 m^4, My = 30 kN m; floor mass 10 t
lumped at the two floor nodes in both translations, no P-Delta; Rayleigh damping
C = a0 M + a1 K0 with the initial stiffness and pound's a0, a1 from the file) under the pulse
x0 = 0.05 m, a = 2 1/s, b = 4 pi rad/s, dt = 1e-3 s, 2 s: Newmark average acceleration with
Newton iterations on the global equations (6 DOFs), each element's two elastic-perfectly-plastic
end hinges by an active-set return mapping (m = S (theta - p), |m| <= My) and its consistent
tangent; the hinges' kinematic hardening moduli H (|m - H p| <= My) are read from the file. Nothing
is shared with pound's LCP formulation. Compares the floor displacement
history, the residual drift and the plastic rotations with pound's results file of the same
portal (the deck is written by tests/cli/hinge_reference.cmake).

With GRAVITY (kN, the floor's gravity load, half at each floor node; pound's deck: p_delta =
.true., gravity_load = GRAVITY) the constant chord geometric stiffness N/L [1 -1; -1 1] of every
element's axial force N from the linear gravity analysis is added (P-Delta; with a mechanism
the tangent turns negative and the portal collapses: the histories are compared up to pound's
collapse step, after which pound holds the building).

usage: reference_frame_hinges.py RESULTS.h5 [GRAVITY]   (exit 1 when a difference exceeds 1e-9)
"""
import sys
import numpy as np, h5py, itertools
E=3e7; h=3.0; L=6.0
Ic=3.75e-4; Ac=0.16; Ib=1e-3; Ab=0.15
Myc=45.0; Myb=30.0
m=10.0; dt=1e-3; T=2.0
x0,a,b=0.05,2.0,12.566370614359172
nodes={1:(0,0),2:(0,h),3:(L,h),4:(L,0)}
free={2:[0,1,2],3:[3,4,5]}
els=[(1,2,E,Ac,Ic,Myc),(4,3,E,Ac,Ic,Myc),(2,3,E,Ab,Ib,Myb)]
def dofs(n): return free.get(n,[None]*3)
def T6(c,s):
    t=np.zeros((6,6)); R=np.array([[c,s,0],[-s,c,0],[0,0,1]]); t[:3,:3]=R; t[3:,3:]=R; return t
class El:
    def __init__(s,n1,n2,E,A,I,My):
        x1,z1=nodes[n1]; x2,z2=nodes[n2]; s.L=np.hypot(x2-x1,z2-z1)
        s.T=T6((x2-x1)/s.L,(z2-z1)/s.L); s.idx=dofs(n1)+dofs(n2)
        s.EA=E*A/s.L; k=E*I/s.L; s.S=np.array([[4*k,2*k],[2*k,4*k]]); s.My=My
        s.p=np.zeros(2); s.ptrial=np.zeros(2); s.H=np.zeros(2)
        L_=s.L; s.B=np.array([[0,1/L_,1,0,-1/L_,0],[0,1/L_,0,0,-1/L_,1]])
    def state(s,ug):
        dg=np.array([ug[i] if i is not None else 0.0 for i in s.idx]); dl=s.T@dg
        th=s.B@dl
        best=None
        for st in itertools.product([0,1,-1],repeat=2):
            p=s.p.copy(); ok=True
            act=[i for i in range(2) if st[i]!=0]
            if act:
                # active i: m_i - H_i p_i = st_i My with m = S (th - p), p = p_n + dp (dp on the
                # active hinges): sum_j (S_ij + H_i d_ij) dp_j = S_i (th - p_n) - H_i p_n,i - st_i My
                A=np.array([[s.S[i,j]+(s.H[i] if i==j else 0.0) for j in act] for i in act])
                rhs=np.array([s.S[i]@(th-s.p) - s.H[i]*s.p[i] - st[i]*s.My for i in act])
                dp=np.linalg.solve(A,rhs)
                for k,i in enumerate(act):
                    if dp[k]*st[i] < -1e-14: ok=False
                    p[i]=s.p[i]+dp[k]
            mm=s.S@(th-p)
            if any(abs(mm[i]-s.H[i]*p[i])>s.My*(1+1e-12) for i in range(2) if st[i]==0): ok=False
            if ok: best=(st,p,mm); break
        st,p,mm=best
        s.ptrial=p
        N=s.EA*(dl[3]-dl[0]); V=(mm[0]+mm[1])/s.L
        fl=np.array([-N,V,mm[0],N,-V,mm[1]])
        # tangent
        act=[i for i in range(2) if st[i]!=0]
        Kt=s.S.copy()
        if act:
            # dm = S dth - S[:,A] (S_AA + H_A)^-1 S[A,:] dth
            SA=s.S[np.ix_(act,act)]+np.diag(s.H[act])
            Kt=s.S-s.S[:,act]@np.linalg.solve(SA,s.S[act,:])
        kl=s.B.T@Kt@s.B; kl[0,0]+=s.EA; kl[0,3]-=s.EA; kl[3,0]-=s.EA; kl[3,3]+=s.EA
        return s.T.T@fl, s.T.T@kl@s.T
E_=[El(*e) for e in els]
n=6; M=np.diag([m/2,m/2,0,m/2,m/2,0]); r=np.array([1,0,0,1,0,0.0])
def ag(t): return x0*np.exp(-a*t)*((a*a-b*b)*np.sin(b*t)-2*a*b*np.cos(b*t))
h5=h5py.File(sys.argv[1], 'r')
a0,a1=h5['model/P/rayleigh'][()]
# Kinematic hardening moduli of the hinges (pound's element order: the columns, then the beam).
for k,e in enumerate(E_):
    e.H=h5['model/P/hinges/hardening_modulus'][()][2*k:2*k+2].copy()
K0=np.zeros((n,n))
for e in E_:
    kl=e.B.T@e.S@e.B; kl[0,0]+=e.EA; kl[0,3]-=e.EA; kl[3,0]-=e.EA; kl[3,3]+=e.EA
    kg=e.T.T@kl@e.T
    for i,gi in enumerate(e.idx):
        for j,gj in enumerate(e.idx):
            if gi is not None and gj is not None: K0[gi,gj]+=kg[i,j]
gravity=float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
G=np.zeros((n,n))
if gravity > 0.0:
    fg=np.zeros(n); fg[1]=fg[4]=-gravity/2
    ugr=np.linalg.solve(K0,fg)
    for e in E_:
        dl=e.T@np.array([ugr[i] if i is not None else 0.0 for i in e.idx])
        N=e.EA*(dl[3]-dl[0])
        gl=np.zeros((6,6)); gl[np.ix_([1,4],[1,4])]=N/e.L*np.array([[1,-1],[-1,1]])
        gg=e.T.T@gl@e.T
        for i,gi in enumerate(e.idx):
            for j,gj in enumerate(e.idx):
                if gi is not None and gj is not None: G[gi,gj]+=gg[i,j]
    K0=K0+G
C=a0*M+a1*K0
u=np.zeros(n); v=np.zeros(n); acc=-r*ag(0.0)
N=int(round(T/dt)); hist=[u[3]]
# Up to pound's collapse step (pound holds the building after it).
if h5['uncoupled/P'].attrs['collapse_storey'] > 0:
    N=int(round(h5['uncoupled/P'].attrs['collapse_time']/dt))
for k in range(1,N+1):
    t=k*dt; un=u.copy()
    for it in range(50):
        an=4/dt**2*(u-un)-4/dt*v-acc
        F=np.zeros(n); K=np.zeros((n,n))
        for e in E_:
            f,kg=e.state(u)
            for i,gi in enumerate(e.idx):
                if gi is None: continue
                F[gi]+=f[i]
                for j,gj in enumerate(e.idx):
                    if gj is None: continue
                    K[gi,gj]+=kg[i,j]
        vn=2/dt*(u-un)-v
        R=M@an+C@vn+F+G@u+M@r*ag(t)
        if np.max(abs(R))<1e-9 and it>0: break
        du=np.linalg.solve(K+G+4/dt**2*M+2/dt*C,-R); u=u+du
    anew=4/dt**2*(u-un)-4/dt*v-acc; v=2/dt*(u-un)-v; acc=anew
    for e in E_: e.p=e.ptrial.copy()
    hist.append(u[3])
hist=np.array(hist)
U=h5['uncoupled/P/u'][()]
up=U[:, 0]
end=len(hist)
if h5['uncoupled/P'].attrs['collapse_storey'] > 0:
    end=int(round(h5['uncoupled/P'].attrs['collapse_time']/dt))+1
    print('collapse at t = %.4f s: compared up to it' % h5['uncoupled/P'].attrs['collapse_time'])
du=abs(up[:end]-hist[:end]).max()
dres=abs(h5['uncoupled/P/residual_drift'][()][0]-hist[end-1])
print('peak |u|: pound %.12e, reference %.12e; largest difference of u %.3e m; of the residual drift %.3e m'
      % (abs(up[:end]).max(), abs(hist[:end]).max(), du, dres))
sys.exit(0 if du <= 1e-9 and dres <= 1e-9 else 1)
