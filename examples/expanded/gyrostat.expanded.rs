/// Heavy rigid body about a fixed point carrying a rotor, with a linear gyroscopic term.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5*omega.dot(inertia*omega),
    linear = (rotor+coupling*gamma).dot(omega),
    potential = mass*g*com.dot(gamma),
)]
pub struct Gyrostat {
    /// The inertia tensor (symmetric: only its upper triangle is read).
    #[lagrangian(symmetric)]
    pub inertia: Matrix3<f64>,
    pub rotor: Vector3<f64>,
    pub coupling: Matrix3<f64>,
    pub com: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}
#[doc(hidden)]
#[allow(
    non_upper_case_globals,
    unused_qualifications,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
const _: () = {
    type __F64 = ::routh::__private::f64;
    type __Vector3 = ::routh::__private::Vector3<::routh::__private::f64>;
    type __Matrix3 = ::routh::__private::Matrix3<::routh::__private::f64>;
    type __RouthBundle = ::routh::__private::RouthBundle;
    type __GyroscopicSystem = ::routh::__private::GyroscopicSystem;
    type __FullEquations = ::routh::__private::FullEquations;
    type __FullJacobian = ::routh::__private::FullJacobian;
    type __ReducedEquations = ::routh::__private::ReducedEquations;
    type __Op = ::routh::__private::Op;
    type __Output = ::routh::__private::Output;
    type __Tape = ::routh::__private::Tape;
    type __CertificationTape = ::routh::__private::CertificationTape;
    type __RouthianTape = ::routh::__private::RouthianTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
    type __MaybeRouthianTape = ::routh::__private::MaybeRouthianTape;
    type __FlowTape = ::routh::__private::FlowTape;
    type __MaybeFlowTape = ::routh::__private::MaybeFlowTape;
    type __MaybeRankOne = ::routh::__private::MaybeRankOne;
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for Gyrostat {
        #[inline]
        fn lagrangian(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t77 = __v25 * __v3;
            let __t67 = __t66 + __t65;
            let __t78 = __v26 * __v4;
            let __t47 = __t36 * __v0;
            let __t48 = __t41 * __v1;
            let __t46 = __t45 + __t44;
            let __t71 = __t68 * __v0;
            let __t72 = __t69 * __v1;
            let __t79 = __v27 * __v5;
            let __t70 = __t67 + __v15;
            let __t80 = __t78 + __t77;
            let __t76 = __v29 * __v28;
            let __t50 = __t48 + __t47;
            let __t49 = __t46 * __v2;
            let __t74 = __t72 + __t71;
            let __t73 = __t70 * __v2;
            let __t81 = __t80 + __t79;
            let __t51 = __t49 + __t50;
            let __t75 = __t73 + __t74;
            let __t82 = __t81 * __t76;
            let __t52 = __t51 * 0.5f64;
            let __t84 = __t75 - __t82;
            let __t85 = __t84 + __t52;
            __t85
        }
        #[inline]
        fn dl_domega(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t67 = __t66 + __t65;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t46 = __t45 + __t44;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t99 = __t70 + __t46;
            __Vector3::new(__t91, __t95, __t99)
        }
        #[inline]
        fn dl_dgamma(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t76 = __v29 * __v28;
            let __t105 = __v22 * __v2;
            let __t113 = __v23 * __v2;
            let __t104 = __t103 + __t102;
            let __t121 = __v24 * __v2;
            let __t112 = __t111 + __t110;
            let __t120 = __t119 + __t118;
            let __t100 = __t76 * __v25;
            let __t108 = __t76 * __v26;
            let __t116 = __t76 * __v27;
            let __t106 = __t104 + __t105;
            let __t114 = __t112 + __t113;
            let __t122 = __t120 + __t121;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            __Vector3::new(__t107, __t115, __t123)
        }
        #[inline]
        fn d2l_domega2(&self, __gamma: &__Vector3) -> __Matrix3 {
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            __Matrix3::new(__v7, __v8, __v9, __v8, __v10, __v11, __v9, __v11, __v12)
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __Matrix3 {
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            __Matrix3::new(__v16, __v17, __v18, __v19, __v20, __v21, __v22, __v23, __v24)
        }
        #[inline]
        fn energy(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t77 = __v25 * __v3;
            let __t67 = __t66 + __t65;
            let __t78 = __v26 * __v4;
            let __t47 = __t36 * __v0;
            let __t48 = __t41 * __v1;
            let __t46 = __t45 + __t44;
            let __t71 = __t68 * __v0;
            let __t72 = __t69 * __v1;
            let __t79 = __v27 * __v5;
            let __t70 = __t67 + __v15;
            let __t80 = __t78 + __t77;
            let __t76 = __v29 * __v28;
            let __t50 = __t48 + __t47;
            let __t49 = __t46 * __v2;
            let __t91 = __t68 + __t36;
            let __t74 = __t72 + __t71;
            let __t95 = __t69 + __t41;
            let __t73 = __t70 * __v2;
            let __t81 = __t80 + __t79;
            let __t99 = __t70 + __t46;
            let __t51 = __t49 + __t50;
            let __t124 = __t91 * __v0;
            let __t125 = __t95 * __v1;
            let __t75 = __t73 + __t74;
            let __t82 = __t81 * __t76;
            let __t126 = __t99 * __v2;
            let __t52 = __t51 * 0.5f64;
            let __t127 = __t125 + __t124;
            let __t84 = __t75 - __t82;
            let __t128 = __t127 + __t126;
            let __t85 = __t84 + __t52;
            let __t130 = __t128 - __t85;
            __t130
        }
        #[inline]
        fn cyclic_momentum(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t67 = __t66 + __t65;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t70 = __t67 + __v15;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t135 = __t133 + __t134;
            __t135
        }
        #[inline]
        fn full_equations(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullEquations {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t67 = __t66 + __t65;
            let __t76 = __v29 * __v28;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t112 = __t111 + __t110;
            let __t113 = __v23 * __v2;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t46 = __t45 + __t44;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t70 = __t67 + __v15;
            let __t100 = __t76 * __v25;
            let __t106 = __t105 + __t104;
            let __t108 = __t76 * __v26;
            let __t114 = __t113 + __t112;
            let __t116 = __t76 * __v27;
            let __t122 = __t121 + __t120;
            let __t1414 = __v4 * __v2;
            let __t1415 = __v5 * __v1;
            let __t1418 = __v5 * __v0;
            let __t1419 = __v3 * __v2;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t99 = __t70 + __t46;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            let __t1417 = __t1414 - __t1415;
            let __t1421 = __t1418 - __t1419;
            let __t1422 = __v3 * __v1;
            let __t1423 = __v4 * __v0;
            let __t1441 = __t95 * __v2;
            let __t1442 = __t99 * __v1;
            let __t1445 = __t99 * __v0;
            let __t1446 = __t91 * __v2;
            let __t1426 = __t1417 * __v16;
            let __t1427 = __t1421 * __v17;
            let __t1431 = __t1417 * __v19;
            let __t1425 = __t1422 - __t1423;
            let __t1432 = __t1421 * __v20;
            let __t1436 = __t1417 * __v22;
            let __t1437 = __t1421 * __v23;
            let __t1449 = __t91 * __v1;
            let __t1450 = __t95 * __v0;
            let __t1453 = __t115 * __v5;
            let __t1454 = __t123 * __v4;
            let __t1457 = __t123 * __v3;
            let __t1458 = __t107 * __v5;
            let __t1461 = __t107 * __v4;
            let __t1462 = __t115 * __v3;
            let __t1428 = __t1425 * __v18;
            let __t1429 = __t1427 + __t1426;
            let __t1433 = __t1425 * __v21;
            let __t1434 = __t1432 + __t1431;
            let __t1438 = __t1425 * __v24;
            let __t1439 = __t1437 + __t1436;
            let __t1444 = __t1441 - __t1442;
            let __t1448 = __t1445 - __t1446;
            let __t1452 = __t1449 - __t1450;
            let __t1456 = __t1453 - __t1454;
            let __t1460 = __t1457 - __t1458;
            let __t1464 = __t1461 - __t1462;
            let __t1430 = __t1429 + __t1428;
            let __t1435 = __t1434 + __t1433;
            let __t1440 = __t1439 + __t1438;
            let __t1465 = __t1456 + __t1444;
            let __t1468 = __t1460 + __t1448;
            let __t1471 = __t1464 + __t1452;
            let __t1467 = __t1465 - __t1430;
            let __t1470 = __t1468 - __t1435;
            let __t1473 = __t1471 - __t1440;
            __FullEquations {
                inertia: __Matrix3::new(
                    __v7,
                    __v8,
                    __v9,
                    __v8,
                    __v10,
                    __v11,
                    __v9,
                    __v11,
                    __v12,
                ),
                right_side: __Vector3::new(__t1467, __t1470, __t1473),
                rank_one: __MaybeRankOne::None,
            }
        }
        #[inline]
        fn full_jacobian(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullJacobian {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t67 = __t66 + __t65;
            let __t76 = __v29 * __v28;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t112 = __t111 + __t110;
            let __t113 = __v23 * __v2;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t46 = __t45 + __t44;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t70 = __t67 + __v15;
            let __t100 = __t76 * __v25;
            let __t106 = __t105 + __t104;
            let __t108 = __t76 * __v26;
            let __t114 = __t113 + __t112;
            let __t116 = __t76 * __v27;
            let __t122 = __t121 + __t120;
            let __t1414 = __v4 * __v2;
            let __t1415 = __v5 * __v1;
            let __t1418 = __v5 * __v0;
            let __t1419 = __v3 * __v2;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t99 = __t70 + __t46;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            let __t1417 = __t1414 - __t1415;
            let __t1421 = __t1418 - __t1419;
            let __t1422 = __v3 * __v1;
            let __t1423 = __v4 * __v0;
            let __t1636 = __t116 - __t118;
            let __t1653 = __t110 - __t108;
            let __t1664 = __t119 - __t116;
            let __t1687 = __t100 - __t103;
            let __t1703 = __t108 - __t110;
            let __t1715 = __t102 - __t100;
            let __t186 = __v19 * __v4;
            let __t187 = __v22 * __v5;
            let __t191 = __v17 * __v3;
            let __t192 = __v23 * __v5;
            let __t196 = __v18 * __v3;
            let __t197 = __v21 * __v4;
            let __t1425 = __t1422 - __t1423;
            let __t1426 = __t1417 * __v16;
            let __t1427 = __t1421 * __v17;
            let __t1431 = __t1417 * __v19;
            let __t1432 = __t1421 * __v20;
            let __t1436 = __t1417 * __v22;
            let __t1437 = __t1421 * __v23;
            let __t1441 = __t95 * __v2;
            let __t1442 = __t99 * __v1;
            let __t1445 = __t99 * __v0;
            let __t1446 = __t91 * __v2;
            let __t1449 = __t91 * __v1;
            let __t1450 = __t95 * __v0;
            let __t1453 = __t115 * __v5;
            let __t1454 = __t123 * __v4;
            let __t1457 = __t123 * __v3;
            let __t1458 = __t107 * __v5;
            let __t1461 = __t107 * __v4;
            let __t1462 = __t115 * __v3;
            let __t1535 = __v16 * __v5;
            let __t1540 = __v20 * __v5;
            let __t1542 = __t99 + __t43;
            let __t1544 = __v10 * __v2;
            let __t1550 = __v16 * __v4;
            let __t1553 = __v24 * __v4;
            let __t1556 = __v12 * __v1;
            let __t1558 = __t95 + __t39;
            let __t1563 = __v7 * __v2;
            let __t1565 = __t99 + __t42;
            let __t1578 = __v20 * __v3;
            let __t1583 = __v24 * __v3;
            let __t1585 = __t91 + __t34;
            let __t1587 = __v12 * __v0;
            let __t1592 = __t95 + __t37;
            let __t1594 = __v7 * __v1;
            let __t1599 = __v10 * __v0;
            let __t1601 = __t91 + __t33;
            let __t1624 = __v16 * __v2;
            let __t1638 = __t1636 - __t121;
            let __t1644 = __v16 * __v1;
            let __t1654 = __t1653 + __t113;
            let __t1665 = __t1664 + __t121;
            let __t1676 = __v20 * __v0;
            let __t1689 = __t1687 - __t105;
            let __t1705 = __t1703 - __t111;
            let __t1716 = __t1715 + __t103;
            let __t1428 = __t1425 * __v18;
            let __t1429 = __t1427 + __t1426;
            let __t1433 = __t1425 * __v21;
            let __t1434 = __t1432 + __t1431;
            let __t1438 = __t1425 * __v24;
            let __t1439 = __t1437 + __t1436;
            let __t1444 = __t1441 - __t1442;
            let __t1448 = __t1445 - __t1446;
            let __t1452 = __t1449 - __t1450;
            let __t1456 = __t1453 - __t1454;
            let __t1460 = __t1457 - __t1458;
            let __t1464 = __t1461 - __t1462;
            let __t1537 = __t196 - __t1535;
            let __t1541 = __t1540 - __t197;
            let __t1545 = __t1544 - __t1542;
            let __t1551 = __t1550 - __t191;
            let __t1555 = __t192 - __t1553;
            let __t1559 = __t1558 - __t1556;
            let __t1566 = __t1565 - __t1563;
            let __t1580 = __t186 - __t1578;
            let __t1584 = __t1583 - __t187;
            let __t1588 = __t1587 - __t1585;
            let __t1595 = __t1594 - __t1592;
            let __t1602 = __t1601 - __t1599;
            let __t1614 = __v17 * __v2;
            let __t1616 = __v18 * __v1;
            let __t1619 = __v22 * __v1;
            let __t1621 = __v19 * __v2;
            let __t1630 = __v23 * __v1;
            let __t1632 = __v20 * __v2;
            let __t1640 = __t1638 - __t1624;
            let __t1648 = __v24 * __v1;
            let __t1655 = __t1654 + __t1644;
            let __t1666 = __t1665 - __t1624;
            let __t1669 = __v21 * __v0;
            let __t1673 = __v23 * __v0;
            let __t1681 = __v18 * __v2;
            let __t1683 = __v24 * __v0;
            let __t1691 = __t1689 - __t1676;
            let __t1706 = __t1705 + __t1644;
            let __t1717 = __t1716 - __t1676;
            let __t1430 = __t1429 + __t1428;
            let __t1435 = __t1434 + __t1433;
            let __t1440 = __t1439 + __t1438;
            let __t1465 = __t1456 + __t1444;
            let __t1468 = __t1460 + __t1448;
            let __t1471 = __t1464 + __t1452;
            let __t1528 = __v9 * __v1;
            let __t1530 = __v8 * __v2;
            let __t1546 = __t1545 + __t1541;
            let __t1560 = __t1559 + __t1555;
            let __t1567 = __t1566 + __t1537;
            let __t1575 = __v11 * __v0;
            let __t1589 = __t1588 + __t1584;
            let __t1596 = __t1595 + __t1551;
            let __t1603 = __t1602 + __t1580;
            let __t1617 = __t1616 - __t1614;
            let __t1622 = __t1621 - __t1619;
            let __t1641 = __t1640 - __t1630;
            let __t1650 = __v21 * __v2;
            let __t1656 = __t1655 - __t1648;
            let __t1661 = __v22 * __v0;
            let __t1667 = __t1666 + __t1632;
            let __t1671 = __t1621 - __t1669;
            let __t1674 = __t1673 - __t1614;
            let __t1692 = __t1691 - __t1681;
            let __t1698 = __v19 * __v0;
            let __t1707 = __t1706 - __t1648;
            let __t1712 = __v17 * __v1;
            let __t1718 = __t1717 + __t1683;
            let __t1720 = __t1673 - __t1619;
            let __t1722 = __t1616 - __t1669;
            let __t1467 = __t1465 - __t1430;
            let __t1470 = __t1468 - __t1435;
            let __t1473 = __t1471 - __t1440;
            let __t1531 = __t1530 - __t1528;
            let __t1547 = __t1546 - __t1537;
            let __t1561 = __t1560 - __t1551;
            let __t1568 = __t1567 - __t1541;
            let __t1576 = __t1575 - __t1530;
            let __t1590 = __t1589 - __t1580;
            let __t1597 = __t1596 - __t1555;
            let __t1604 = __t1603 - __t1584;
            let __t1611 = __t1528 - __t1575;
            let __t1623 = __t1622 - __t1617;
            let __t1642 = __t1641 + __t1632;
            let __t1657 = __t1656 + __t1650;
            let __t1668 = __t1667 + __t1661;
            let __t1675 = __t1674 - __t1671;
            let __t1693 = __t1692 + __t1683;
            let __t1708 = __t1707 - __t1698;
            let __t1719 = __t1718 + __t1712;
            let __t1723 = __t1722 - __t1720;
            __FullJacobian {
                inertia: __Matrix3::new(
                    __v7,
                    __v8,
                    __v9,
                    __v8,
                    __v10,
                    __v11,
                    __v9,
                    __v11,
                    __v12,
                ),
                right_side: __Vector3::new(__t1467, __t1470, __t1473),
                dright_domega: __Matrix3::new(
                    __t1531,
                    __t1547,
                    __t1561,
                    __t1568,
                    __t1576,
                    __t1590,
                    __t1597,
                    __t1604,
                    __t1611,
                ),
                dright_dgamma: __Matrix3::new(
                    __t1623,
                    __t1642,
                    __t1657,
                    __t1668,
                    __t1675,
                    __t1693,
                    __t1708,
                    __t1719,
                    __t1723,
                ),
                dinertia_dgamma: [
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                ],
            }
        }
        #[inline]
        fn flow_tape(&self) -> __MaybeFlowTape {
            static __FLOW_OPS: [__Op; 111] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Param(11),
                __Op::Param(12),
                __Op::Param(13),
                __Op::Param(14),
                __Op::Param(15),
                __Op::Param(16),
                __Op::Param(17),
                __Op::Param(18),
                __Op::Param(19),
                __Op::Param(20),
                __Op::Param(21),
                __Op::Param(22),
                __Op::Const(0x3fe0000000000000),
                __Op::Mul(0, 6),
                __Op::Mul(1, 7),
                __Op::Mul(2, 8),
                __Op::Add(30, 31),
                __Op::Add(32, 33),
                __Op::Mul(0, 7),
                __Op::Mul(1, 9),
                __Op::Mul(2, 10),
                __Op::Add(35, 36),
                __Op::Add(37, 38),
                __Op::Mul(0, 8),
                __Op::Mul(1, 10),
                __Op::Mul(2, 11),
                __Op::Add(40, 41),
                __Op::Add(42, 43),
                __Op::Mul(0, 34),
                __Op::Mul(1, 39),
                __Op::Mul(2, 44),
                __Op::Add(45, 46),
                __Op::Add(47, 48),
                __Op::Mul(29, 49),
                __Op::Mul(3, 15),
                __Op::Mul(4, 16),
                __Op::Mul(5, 17),
                __Op::Add(51, 52),
                __Op::Add(53, 54),
                __Op::Mul(3, 18),
                __Op::Mul(4, 19),
                __Op::Mul(5, 20),
                __Op::Add(56, 57),
                __Op::Add(58, 59),
                __Op::Mul(3, 21),
                __Op::Mul(4, 22),
                __Op::Mul(5, 23),
                __Op::Add(61, 62),
                __Op::Add(63, 64),
                __Op::Add(12, 55),
                __Op::Add(13, 60),
                __Op::Add(14, 65),
                __Op::Mul(0, 66),
                __Op::Mul(1, 67),
                __Op::Mul(2, 68),
                __Op::Add(69, 70),
                __Op::Add(71, 72),
                __Op::Mul(27, 28),
                __Op::Mul(3, 24),
                __Op::Mul(4, 25),
                __Op::Mul(5, 26),
                __Op::Add(75, 76),
                __Op::Add(77, 78),
                __Op::Mul(74, 79),
                __Op::Neg(80),
                __Op::Add(73, 81),
                __Op::Add(50, 82),
                __Op::Add(34, 66),
                __Op::Add(39, 67),
                __Op::Add(44, 68),
                __Op::Mul(24, 74),
                __Op::Neg(87),
                __Op::Mul(1, 18),
                __Op::Mul(0, 15),
                __Op::Add(89, 90),
                __Op::Mul(2, 21),
                __Op::Add(91, 92),
                __Op::Add(88, 93),
                __Op::Mul(25, 74),
                __Op::Neg(95),
                __Op::Mul(1, 19),
                __Op::Mul(0, 16),
                __Op::Add(97, 98),
                __Op::Mul(2, 22),
                __Op::Add(99, 100),
                __Op::Add(96, 101),
                __Op::Mul(26, 74),
                __Op::Neg(103),
                __Op::Mul(1, 20),
                __Op::Mul(0, 17),
                __Op::Add(105, 106),
                __Op::Mul(2, 23),
                __Op::Add(107, 108),
                __Op::Add(104, 109),
            ];
            static __FLOW_OUT: [__Output; 22] = [
                __Output {
                    name: "lagrangian",
                    slot: 83,
                },
                __Output {
                    name: "dl_domega[0]",
                    slot: 84,
                },
                __Output {
                    name: "dl_domega[1]",
                    slot: 85,
                },
                __Output {
                    name: "dl_domega[2]",
                    slot: 86,
                },
                __Output {
                    name: "dl_dgamma[0]",
                    slot: 94,
                },
                __Output {
                    name: "dl_dgamma[1]",
                    slot: 102,
                },
                __Output {
                    name: "dl_dgamma[2]",
                    slot: 110,
                },
                __Output {
                    name: "d2l_domega2[0][0]",
                    slot: 6,
                },
                __Output {
                    name: "d2l_domega2[0][1]",
                    slot: 7,
                },
                __Output {
                    name: "d2l_domega2[0][2]",
                    slot: 8,
                },
                __Output {
                    name: "d2l_domega2[1][1]",
                    slot: 9,
                },
                __Output {
                    name: "d2l_domega2[1][2]",
                    slot: 10,
                },
                __Output {
                    name: "d2l_domega2[2][2]",
                    slot: 11,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][0]",
                    slot: 15,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][1]",
                    slot: 16,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][2]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][0]",
                    slot: 18,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][1]",
                    slot: 19,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][2]",
                    slot: 20,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][0]",
                    slot: 21,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][1]",
                    slot: 22,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][2]",
                    slot: 23,
                },
            ];
            static __FLOW: __Tape = __Tape::from_static(&__FLOW_OPS, &__FLOW_OUT, 23);
            __FlowTape::new(
                    __Tape::clone(&__FLOW),
                    <[__F64]>::to_vec(
                        &[
                            self.inertia[(0usize, 0usize)],
                            self.inertia[(0usize, 1usize)],
                            self.inertia[(0usize, 2usize)],
                            self.inertia[(1usize, 1usize)],
                            self.inertia[(1usize, 2usize)],
                            self.inertia[(2usize, 2usize)],
                            self.rotor[0usize],
                            self.rotor[1usize],
                            self.rotor[2usize],
                            self.coupling[(0usize, 0usize)],
                            self.coupling[(0usize, 1usize)],
                            self.coupling[(0usize, 2usize)],
                            self.coupling[(1usize, 0usize)],
                            self.coupling[(1usize, 1usize)],
                            self.coupling[(1usize, 2usize)],
                            self.coupling[(2usize, 0usize)],
                            self.coupling[(2usize, 1usize)],
                            self.coupling[(2usize, 2usize)],
                            self.com[0usize],
                            self.com[1usize],
                            self.com[2usize],
                            self.mass,
                            self.g,
                        ],
                    ),
                )
                .ok()
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for Gyrostat {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t136 = __v7 * __v3;
            let __t67 = __t66 + __t65;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t138 = __v9 * __v5;
            let __t70 = __t67 + __v15;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t140 = __t139 + __t138;
            let __t148 = __v12 * __v5;
            let __t145 = __t144 + __t143;
            let __t149 = __t147 + __t146;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t150 = __t149 + __t148;
            let __t135 = __t133 + __t134;
            let __t154 = __t152 + __t151;
            let __t153 = __t150 * __v5;
            let __t158 = __v6 - __t135;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            __t160
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t136 = __v7 * __v3;
            let __t67 = __t66 + __t65;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t138 = __v9 * __v5;
            let __t70 = __t67 + __v15;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t140 = __t139 + __t138;
            let __t148 = __v12 * __v5;
            let __t145 = __t144 + __t143;
            let __t167 = __t91 + __t68;
            let __t149 = __t147 + __t146;
            let __t168 = __t95 + __t69;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t151 = __t140 * __v3;
            let __t76 = __v29 * __v28;
            let __t152 = __t145 * __v4;
            let __t169 = __t99 + __t70;
            let __t150 = __t149 + __t148;
            let __t170 = __t167 * __v0;
            let __t171 = __t168 * __v1;
            let __t135 = __t133 + __t134;
            let __t100 = __t76 * __v25;
            let __t154 = __t152 + __t151;
            let __t108 = __t76 * __v26;
            let __t153 = __t150 * __v5;
            let __t172 = __t169 * __v2;
            let __t173 = __t171 + __t170;
            let __t158 = __v6 - __t135;
            let __t116 = __t76 * __v27;
            let __t178 = __t100 * __v3;
            let __t179 = __t108 * __v4;
            let __t155 = __t153 + __t154;
            let __t174 = __t173 + __t172;
            let __t180 = __t116 * __v5;
            let __t181 = __t179 + __t178;
            let __t160 = __t158 / __t155;
            let __t182 = __t181 + __t180;
            let __t162 = __t160 * __t158;
            let __t176 = __t174 - __t162;
            let __t177 = __t176 * 0.5f64;
            let __t185 = __t177 - __t182;
            __t185
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t136 = __v7 * __v3;
            let __t67 = __t66 + __t65;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t138 = __v9 * __v5;
            let __t70 = __t67 + __v15;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t140 = __t139 + __t138;
            let __t148 = __v12 * __v5;
            let __t145 = __t144 + __t143;
            let __t149 = __t147 + __t146;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t150 = __t149 + __t148;
            let __t135 = __t133 + __t134;
            let __t154 = __t152 + __t151;
            let __t153 = __t150 * __v5;
            let __t158 = __v6 - __t135;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t210 = __t160 * __t140;
            let __t211 = __t160 * __t145;
            let __t212 = __t160 * __t150;
            let __t216 = __t210 + __t91;
            let __t217 = __t211 + __t95;
            let __t218 = __t212 + __t99;
            __Vector3::new(__t216, __t217, __t218)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t136 = __v7 * __v3;
            let __t67 = __t66 + __t65;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t138 = __v9 * __v5;
            let __t70 = __t67 + __v15;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t140 = __t139 + __t138;
            let __t148 = __v12 * __v5;
            let __t145 = __t144 + __t143;
            let __t186 = __v19 * __v4;
            let __t149 = __t147 + __t146;
            let __t191 = __v17 * __v3;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t151 = __t140 * __v3;
            let __t196 = __v18 * __v3;
            let __t152 = __t145 * __v4;
            let __t197 = __v21 * __v4;
            let __t150 = __t149 + __t148;
            let __t187 = __v22 * __v5;
            let __t188 = __t186 + __t53;
            let __t135 = __t133 + __t134;
            let __t192 = __v23 * __v5;
            let __t193 = __t191 + __t59;
            let __t154 = __t152 + __t151;
            let __t198 = __t197 + __t196;
            let __t153 = __t150 * __v5;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t158 = __v6 - __t135;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t155 = __t153 + __t154;
            let __t189 = __t188 + __t187;
            let __t194 = __t193 + __t192;
            let __t199 = __t198 + __t65;
            let __t76 = __v29 * __v28;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t112 = __t111 + __t110;
            let __t160 = __t158 / __t155;
            let __t113 = __v23 * __v2;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t190 = __t189 + __t91;
            let __t195 = __t194 + __t95;
            let __t200 = __t199 + __t99;
            let __t100 = __t76 * __v25;
            let __t106 = __t105 + __t104;
            let __t108 = __t76 * __v26;
            let __t114 = __t113 + __t112;
            let __t116 = __t76 * __v27;
            let __t122 = __t121 + __t120;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            let __t210 = __t160 * __t140;
            let __t211 = __t160 * __t145;
            let __t212 = __t160 * __t150;
            let __t213 = __t210 + __t190;
            let __t214 = __t211 + __t195;
            let __t215 = __t212 + __t200;
            let __t219 = __t213 * __t160;
            let __t221 = __t214 * __t160;
            let __t223 = __t215 * __t160;
            let __t220 = __t219 + __t107;
            let __t222 = __t221 + __t115;
            let __t224 = __t223 + __t123;
            __Vector3::new(__t220, __t222, __t224)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t136 = __v7 * __v3;
            let __t67 = __t66 + __t65;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t46 = __t45 + __t44;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t138 = __v9 * __v5;
            let __t70 = __t67 + __v15;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t99 = __t70 + __t46;
            let __t140 = __t139 + __t138;
            let __t148 = __v12 * __v5;
            let __t145 = __t144 + __t143;
            let __t149 = __t147 + __t146;
            let __t134 = __t132 + __t131;
            let __t133 = __t99 * __v5;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t150 = __t149 + __t148;
            let __t135 = __t133 + __t134;
            let __t154 = __t152 + __t151;
            let __t153 = __t150 * __v5;
            let __t158 = __v6 - __t135;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t333 = -__t160;
            __t333
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t138 = __v9 * __v5;
            let __t143 = __v11 * __v5;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t148 = __v12 * __v5;
            let __t139 = __t137 + __t136;
            let __t144 = __t142 + __t141;
            let __t149 = __t147 + __t146;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t155 = __t154 + __t153;
            let __t159 = 1.0f64 / __t155;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t233 = __t159 * __t150;
            let __t237 = __t231 * __t140;
            let __t240 = __t231 * __t145;
            let __t243 = __t231 * __t150;
            let __t261 = __t232 * __t145;
            let __t264 = __t232 * __t150;
            let __t281 = __t233 * __t150;
            let __t239 = __v7 - __t237;
            let __t242 = __v8 - __t240;
            let __t245 = __v9 - __t243;
            let __t263 = __v10 - __t261;
            let __t266 = __v11 - __t264;
            let __t283 = __v12 - __t281;
            __Matrix3::new(
                __t239,
                __t242,
                __t245,
                __t242,
                __t263,
                __t266,
                __t245,
                __t266,
                __t283,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t138 = __v9 * __v5;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t67 = __t66 + __t65;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t186 = __v19 * __v4;
            let __t191 = __v17 * __v3;
            let __t46 = __t45 + __t44;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t196 = __v18 * __v3;
            let __t155 = __t154 + __t153;
            let __t197 = __v21 * __v4;
            let __t187 = __v22 * __v5;
            let __t188 = __t186 + __t53;
            let __t99 = __t70 + __t46;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t192 = __v23 * __v5;
            let __t159 = 1.0f64 / __t155;
            let __t193 = __t191 + __t59;
            let __t198 = __t197 + __t196;
            let __t189 = __t188 + __t187;
            let __t133 = __t99 * __v5;
            let __t203 = __t140 * 2f64;
            let __t134 = __t132 + __t131;
            let __t206 = __t145 * 2f64;
            let __t209 = __t150 * 2f64;
            let __t194 = __t193 + __t192;
            let __t199 = __t198 + __t65;
            let __t190 = __t189 + __t91;
            let __t135 = __t134 + __t133;
            let __t195 = __t194 + __t95;
            let __t200 = __t199 + __t99;
            let __t158 = __v6 - __t135;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t160 = __t158 * __t159;
            let __t233 = __t159 * __t150;
            let __t225 = __t160 * __t203;
            let __t227 = __t160 * __t206;
            let __t229 = __t160 * __t209;
            let __t246 = __t160 * __v7;
            let __t251 = __t160 * __v8;
            let __t256 = __t160 * __v9;
            let __t271 = __t160 * __v10;
            let __t276 = __t160 * __v11;
            let __t226 = __t225 + __t190;
            let __t228 = __t227 + __t195;
            let __t230 = __t229 + __t200;
            let __t292 = __t160 * __v12;
            let __t247 = __t246 + __v16;
            let __t252 = __t251 + __v17;
            let __t257 = __t256 + __v18;
            let __t267 = __t251 + __v19;
            let __t248 = __t226 * __t231;
            let __t253 = __t228 * __t231;
            let __t258 = __t230 * __t231;
            let __t268 = __t226 * __t232;
            let __t272 = __t271 + __v20;
            let __t273 = __t228 * __t232;
            let __t277 = __t276 + __v21;
            let __t278 = __t230 * __t232;
            let __t284 = __t256 + __v22;
            let __t285 = __t226 * __t233;
            let __t288 = __t276 + __v23;
            let __t289 = __t228 * __t233;
            let __t293 = __t292 + __v24;
            let __t294 = __t230 * __t233;
            let __t250 = __t247 - __t248;
            let __t255 = __t252 - __t253;
            let __t260 = __t257 - __t258;
            let __t270 = __t267 - __t268;
            let __t275 = __t272 - __t273;
            let __t280 = __t277 - __t278;
            let __t287 = __t284 - __t285;
            let __t291 = __t288 - __t289;
            let __t296 = __t293 - __t294;
            __Matrix3::new(
                __t250,
                __t255,
                __t260,
                __t270,
                __t275,
                __t280,
                __t287,
                __t291,
                __t296,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t138 = __v9 * __v5;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t67 = __t66 + __t65;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t186 = __v19 * __v4;
            let __t191 = __v17 * __v3;
            let __t46 = __t45 + __t44;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t196 = __v18 * __v3;
            let __t155 = __t154 + __t153;
            let __t197 = __v21 * __v4;
            let __t187 = __v22 * __v5;
            let __t188 = __t186 + __t53;
            let __t99 = __t70 + __t46;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t192 = __v23 * __v5;
            let __t159 = 1.0f64 / __t155;
            let __t193 = __t191 + __t59;
            let __t198 = __t197 + __t196;
            let __t189 = __t188 + __t187;
            let __t133 = __t99 * __v5;
            let __t203 = __t140 * 2f64;
            let __t134 = __t132 + __t131;
            let __t206 = __t145 * 2f64;
            let __t209 = __t150 * 2f64;
            let __t194 = __t193 + __t192;
            let __t199 = __t198 + __t65;
            let __t190 = __t189 + __t91;
            let __t135 = __t134 + __t133;
            let __t195 = __t194 + __t95;
            let __t200 = __t199 + __t99;
            let __t158 = __v6 - __t135;
            let __t160 = __t158 * __t159;
            let __t225 = __t160 * __t203;
            let __t227 = __t160 * __t206;
            let __t229 = __t160 * __t209;
            let __t246 = __t160 * __v7;
            let __t251 = __t160 * __v8;
            let __t256 = __t160 * __v9;
            let __t271 = __t160 * __v10;
            let __t276 = __t160 * __v11;
            let __t292 = __t160 * __v12;
            let __t226 = __t225 + __t190;
            let __t228 = __t227 + __t195;
            let __t230 = __t229 + __t200;
            let __t247 = __t246 + __v16;
            let __t252 = __t251 + __v17;
            let __t257 = __t256 + __v18;
            let __t272 = __t271 + __v20;
            let __t277 = __t276 + __v21;
            let __t293 = __t292 + __v24;
            let __t234 = __t226 * __t159;
            let __t235 = __t228 * __t159;
            let __t236 = __t230 * __t159;
            let __t298 = __t247 + __v16;
            let __t304 = __t252 + __v19;
            let __t310 = __t257 + __v22;
            let __t316 = __t272 + __v20;
            let __t322 = __t277 + __v23;
            let __t328 = __t293 + __v24;
            let __t300 = __t234 * __t226;
            let __t306 = __t234 * __t228;
            let __t299 = __t298 * __t160;
            let __t305 = __t304 * __t160;
            let __t311 = __t310 * __t160;
            let __t312 = __t234 * __t230;
            let __t317 = __t316 * __t160;
            let __t318 = __t235 * __t228;
            let __t323 = __t322 * __t160;
            let __t324 = __t235 * __t230;
            let __t329 = __t328 * __t160;
            let __t330 = __t236 * __t230;
            let __t302 = __t299 - __t300;
            let __t308 = __t305 - __t306;
            let __t314 = __t311 - __t312;
            let __t320 = __t317 - __t318;
            let __t326 = __t323 - __t324;
            let __t332 = __t329 - __t330;
            __Matrix3::new(
                __t302,
                __t308,
                __t314,
                __t308,
                __t320,
                __t326,
                __t314,
                __t326,
                __t332,
            )
        }
        #[inline]
        fn amended_potential(&self, __gamma: &__Vector3, __p_psi: __F64) -> __F64 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t55 = __v18 * __v5;
            let __t60 = __v21 * __v5;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t65 = __v24 * __v5;
            let __t56 = __t54 + __t53;
            let __t136 = __v7 * __v3;
            let __t61 = __t59 + __t58;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t66 = __t64 + __t63;
            let __t138 = __v9 * __v5;
            let __t57 = __t56 + __t55;
            let __t143 = __v11 * __v5;
            let __t62 = __t61 + __t60;
            let __t139 = __t137 + __t136;
            let __t146 = __v9 * __v3;
            let __t144 = __t142 + __t141;
            let __t67 = __t66 + __t65;
            let __t147 = __v11 * __v4;
            let __t68 = __t57 + __v13;
            let __t148 = __v12 * __v5;
            let __t69 = __t62 + __v14;
            let __t140 = __t139 + __t138;
            let __t76 = __v29 * __v28;
            let __t145 = __t144 + __t143;
            let __t70 = __t67 + __v15;
            let __t149 = __t147 + __t146;
            let __t334 = __t68 * __v3;
            let __t335 = __t69 * __v4;
            let __t151 = __t140 * __v3;
            let __t100 = __t76 * __v25;
            let __t152 = __t145 * __v4;
            let __t336 = __t70 * __v5;
            let __t150 = __t149 + __t148;
            let __t108 = __t76 * __v26;
            let __t116 = __t76 * __v27;
            let __t337 = __t335 + __t334;
            let __t178 = __t100 * __v3;
            let __t154 = __t152 + __t151;
            let __t153 = __t150 * __v5;
            let __t179 = __t108 * __v4;
            let __t180 = __t116 * __v5;
            let __t338 = __t337 + __t336;
            let __t155 = __t153 + __t154;
            let __t181 = __t179 + __t178;
            let __t340 = __v6 - __t338;
            let __t182 = __t181 + __t180;
            let __t341 = __t340 / __t155;
            let __t343 = __t341 * __t340;
            let __t345 = __t343 * (-0.5f64);
            let __t351 = __t345 - __t182;
            let __t454 = -__t351;
            __t454
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __RouthBundle {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t138 = __v9 * __v5;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t67 = __t66 + __t65;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t186 = __v19 * __v4;
            let __t191 = __v17 * __v3;
            let __t46 = __t45 + __t44;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t196 = __v18 * __v3;
            let __t155 = __t154 + __t153;
            let __t197 = __v21 * __v4;
            let __t187 = __v22 * __v5;
            let __t188 = __t186 + __t53;
            let __t99 = __t70 + __t46;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t167 = __t91 + __t68;
            let __t159 = 1.0f64 / __t155;
            let __t168 = __t95 + __t69;
            let __t192 = __v23 * __v5;
            let __t193 = __t191 + __t59;
            let __t133 = __t99 * __v5;
            let __t198 = __t197 + __t196;
            let __t134 = __t132 + __t131;
            let __t76 = __v29 * __v28;
            let __t169 = __t99 + __t70;
            let __t170 = __t167 * __v0;
            let __t171 = __t168 * __v1;
            let __t189 = __t188 + __t187;
            let __t194 = __t193 + __t192;
            let __t199 = __t198 + __t65;
            let __t135 = __t134 + __t133;
            let __t203 = __t140 * 2f64;
            let __t206 = __t145 * 2f64;
            let __t209 = __t150 * 2f64;
            let __t100 = __t76 * __v25;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t108 = __t76 * __v26;
            let __t158 = __v6 - __t135;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t172 = __t169 * __v2;
            let __t173 = __t171 + __t170;
            let __t190 = __t189 + __t91;
            let __t160 = __t158 * __t159;
            let __t195 = __t194 + __t95;
            let __t200 = __t199 + __t99;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t112 = __t111 + __t110;
            let __t113 = __v23 * __v2;
            let __t116 = __t76 * __v27;
            let __t225 = __t160 * __t203;
            let __t227 = __t160 * __t206;
            let __t229 = __t160 * __t209;
            let __t246 = __t160 * __v7;
            let __t251 = __t160 * __v8;
            let __t256 = __t160 * __v9;
            let __t271 = __t160 * __v10;
            let __t276 = __t160 * __v11;
            let __t292 = __t160 * __v12;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t162 = __t160 * __t158;
            let __t174 = __t173 + __t172;
            let __t178 = __t100 * __v3;
            let __t179 = __t108 * __v4;
            let __t210 = __t160 * __t140;
            let __t211 = __t160 * __t145;
            let __t212 = __t160 * __t150;
            let __t226 = __t225 + __t190;
            let __t228 = __t227 + __t195;
            let __t230 = __t229 + __t200;
            let __t247 = __t246 + __v16;
            let __t252 = __t251 + __v17;
            let __t257 = __t256 + __v18;
            let __t272 = __t271 + __v20;
            let __t277 = __t276 + __v21;
            let __t293 = __t292 + __v24;
            let __t106 = __t105 + __t104;
            let __t114 = __t113 + __t112;
            let __t122 = __t121 + __t120;
            let __t176 = __t174 - __t162;
            let __t180 = __t116 * __v5;
            let __t181 = __t179 + __t178;
            let __t213 = __t210 + __t190;
            let __t214 = __t211 + __t195;
            let __t215 = __t212 + __t200;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t233 = __t159 * __t150;
            let __t234 = __t226 * __t159;
            let __t235 = __t228 * __t159;
            let __t236 = __t230 * __t159;
            let __t298 = __t247 + __v16;
            let __t304 = __t252 + __v19;
            let __t310 = __t257 + __v22;
            let __t316 = __t272 + __v20;
            let __t322 = __t277 + __v23;
            let __t328 = __t293 + __v24;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            let __t177 = __t176 * 0.5f64;
            let __t182 = __t181 + __t180;
            let __t219 = __t213 * __t160;
            let __t221 = __t214 * __t160;
            let __t223 = __t215 * __t160;
            let __t237 = __t231 * __t140;
            let __t240 = __t231 * __t145;
            let __t243 = __t231 * __t150;
            let __t248 = __t231 * __t226;
            let __t253 = __t231 * __t228;
            let __t258 = __t231 * __t230;
            let __t261 = __t232 * __t145;
            let __t264 = __t232 * __t150;
            let __t267 = __t251 + __v19;
            let __t268 = __t232 * __t226;
            let __t273 = __t232 * __t228;
            let __t278 = __t232 * __t230;
            let __t281 = __t233 * __t150;
            let __t284 = __t256 + __v22;
            let __t285 = __t233 * __t226;
            let __t288 = __t276 + __v23;
            let __t289 = __t233 * __t228;
            let __t294 = __t233 * __t230;
            let __t299 = __t298 * __t160;
            let __t300 = __t234 * __t226;
            let __t305 = __t304 * __t160;
            let __t306 = __t234 * __t228;
            let __t311 = __t310 * __t160;
            let __t312 = __t234 * __t230;
            let __t317 = __t316 * __t160;
            let __t318 = __t235 * __t228;
            let __t323 = __t322 * __t160;
            let __t324 = __t235 * __t230;
            let __t329 = __t328 * __t160;
            let __t330 = __t236 * __t230;
            let __t185 = __t177 - __t182;
            let __t216 = __t210 + __t91;
            let __t217 = __t211 + __t95;
            let __t218 = __t212 + __t99;
            let __t220 = __t219 + __t107;
            let __t222 = __t221 + __t115;
            let __t224 = __t223 + __t123;
            let __t239 = __v7 - __t237;
            let __t242 = __v8 - __t240;
            let __t245 = __v9 - __t243;
            let __t250 = __t247 - __t248;
            let __t255 = __t252 - __t253;
            let __t260 = __t257 - __t258;
            let __t263 = __v10 - __t261;
            let __t266 = __v11 - __t264;
            let __t270 = __t267 - __t268;
            let __t275 = __t272 - __t273;
            let __t280 = __t277 - __t278;
            let __t283 = __v12 - __t281;
            let __t287 = __t284 - __t285;
            let __t291 = __t288 - __t289;
            let __t296 = __t293 - __t294;
            let __t302 = __t299 - __t300;
            let __t308 = __t305 - __t306;
            let __t314 = __t311 - __t312;
            let __t320 = __t317 - __t318;
            let __t326 = __t323 - __t324;
            let __t332 = __t329 - __t330;
            let __t333 = -__t160;
            __RouthBundle {
                routhian: __t185,
                psi_dot: __t160,
                dr_domega: __Vector3::new(__t216, __t217, __t218),
                dr_dgamma: __Vector3::new(__t220, __t222, __t224),
                dr_dp: __t333,
                d2r_domega2: __Matrix3::new(
                    __t239,
                    __t242,
                    __t245,
                    __t242,
                    __t263,
                    __t266,
                    __t245,
                    __t266,
                    __t283,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t250,
                    __t255,
                    __t260,
                    __t270,
                    __t275,
                    __t280,
                    __t287,
                    __t291,
                    __t296,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t302,
                    __t308,
                    __t314,
                    __t308,
                    __t320,
                    __t326,
                    __t314,
                    __t326,
                    __t332,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __GyroscopicSystem {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t138 = __v9 * __v5;
            let __t143 = __v11 * __v5;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t53 = __v16 * __v3;
            let __t139 = __t137 + __t136;
            let __t54 = __v17 * __v4;
            let __t144 = __t142 + __t141;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t55 = __v18 * __v5;
            let __t140 = __t139 + __t138;
            let __t56 = __t54 + __t53;
            let __t145 = __t144 + __t143;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t57 = __t56 + __t55;
            let __t152 = __t145 * __v4;
            let __t65 = __v24 * __v5;
            let __t62 = __t61 + __t60;
            let __t186 = __v19 * __v4;
            let __t66 = __t64 + __t63;
            let __t153 = __t150 * __v5;
            let __t191 = __v17 * __v3;
            let __t68 = __t57 + __v13;
            let __t154 = __t152 + __t151;
            let __t187 = __v22 * __v5;
            let __t69 = __t62 + __v14;
            let __t188 = __t186 + __t53;
            let __t67 = __t66 + __t65;
            let __t192 = __v23 * __v5;
            let __t193 = __t191 + __t59;
            let __t334 = __t68 * __v3;
            let __t155 = __t154 + __t153;
            let __t196 = __v18 * __v3;
            let __t335 = __t69 * __v4;
            let __t197 = __v21 * __v4;
            let __t70 = __t67 + __v15;
            let __t189 = __t188 + __t187;
            let __t194 = __t193 + __t192;
            let __t76 = __v29 * __v28;
            let __t159 = 1.0f64 / __t155;
            let __t297 = 2f64 * __v16;
            let __t337 = __t335 + __t334;
            let __t198 = __t197 + __t196;
            let __t336 = __t70 * __v5;
            let __t352 = __t189 + __t68;
            let __t353 = __t194 + __t69;
            let __t100 = __t76 * __v25;
            let __t108 = __t76 * __v26;
            let __t116 = __t76 * __v27;
            let __t315 = 2f64 * __v20;
            let __t199 = __t198 + __t65;
            let __t338 = __t336 + __t337;
            let __t327 = 2f64 * __v24;
            let __t303 = __v19 + __v17;
            let __t309 = __v22 + __v18;
            let __t321 = __v23 + __v21;
            let __t354 = __t199 + __t70;
            let __t340 = __v6 - __t338;
            let __t341 = __t340 * __t159;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t233 = __t159 * __t150;
            let __t358 = __t341 * __t140;
            let __t359 = __t341 * __t145;
            let __t360 = __t341 * __t150;
            let __t382 = __t341 * __v7;
            let __t401 = __t341 * __v10;
            let __t419 = __t341 * __v12;
            let __t387 = __t341 * __v8;
            let __t392 = __t341 * __v9;
            let __t361 = __t358 + __t352;
            let __t362 = __t359 + __t353;
            let __t363 = __t360 + __t354;
            let __t406 = __t341 * __v11;
            let __t424 = __t382 + __t297;
            let __t439 = __t401 + __t315;
            let __t449 = __t419 + __t327;
            let __t429 = __t387 + __t303;
            let __t367 = __t361 * __t341;
            let __t369 = __t362 * __t341;
            let __t371 = __t363 * __t341;
            let __t374 = __t361 + __t358;
            let __t376 = __t362 + __t359;
            let __t378 = __t363 + __t360;
            let __t425 = __t424 * __t341;
            let __t434 = __t392 + __t309;
            let __t368 = __t367 - __t100;
            let __t370 = __t369 - __t108;
            let __t372 = __t371 - __t116;
            let __t379 = __t374 * __t159;
            let __t380 = __t376 * __t159;
            let __t381 = __t378 * __t159;
            let __t440 = __t439 * __t341;
            let __t444 = __t406 + __t321;
            let __t464 = __t368 * __v3;
            let __t465 = __t370 * __v4;
            let __t450 = __t449 * __t341;
            let __t426 = __t379 * __t374;
            let __t441 = __t380 * __t376;
            let __t451 = __t381 * __t378;
            let __t466 = __t372 * __v5;
            let __t383 = __t382 + __v16;
            let __t384 = __t374 * __t231;
            let __t467 = __t465 + __t464;
            let __t402 = __t401 + __v20;
            let __t403 = __t376 * __t232;
            let __t428 = __t425 - __t426;
            let __t430 = __t429 * __t341;
            let __t431 = __t379 * __t376;
            let __t435 = __t434 * __t341;
            let __t436 = __t379 * __t378;
            let __t443 = __t440 - __t441;
            let __t445 = __t444 * __t341;
            let __t446 = __t380 * __t378;
            let __t453 = __t450 - __t451;
            let __t468 = __t467 + __t466;
            let __t386 = __t383 - __t384;
            let __t405 = __t402 - __t403;
            let __t420 = __t419 + __v24;
            let __t421 = __t378 * __t233;
            let __t433 = __t430 - __t431;
            let __t438 = __t435 - __t436;
            let __t448 = __t445 - __t446;
            let __t470 = __t428 - __t468;
            let __t471 = __t443 - __t468;
            let __t472 = __t453 - __t468;
            let __t455 = __t405 + __t386;
            let __t423 = __t420 - __t421;
            let __t490 = __t433 * __v5;
            let __t486 = __t438 * __v5;
            let __t473 = __t448 * __v5;
            let __t478 = __t448 * __v4;
            let __t477 = __t471 * __v5;
            let __t474 = __t472 * __v4;
            let __t485 = __t472 * __v3;
            let __t489 = __t448 * __v3;
            let __t497 = __t438 * __v4;
            let __t500 = __t433 * __v4;
            let __t501 = __t471 * __v3;
            let __t508 = __t438 * __v3;
            let __t509 = __t470 * __v5;
            let __t516 = __t470 * __v4;
            let __t517 = __t433 * __v3;
            let __t456 = __t423 + __t455;
            let __t476 = __t473 - __t474;
            let __t480 = __t477 - __t478;
            let __t488 = __t485 - __t486;
            let __t492 = __t489 - __t490;
            let __t499 = __t497 - __t489;
            let __t503 = __t500 - __t501;
            let __t511 = __t508 - __t509;
            let __t519 = __t516 - __t517;
            let __t457 = __t456 * 0.5f64;
            let __t237 = __t231 * __t140;
            let __t240 = __t231 * __t145;
            let __t243 = __t231 * __t150;
            let __t261 = __t232 * __t145;
            let __t264 = __t232 * __t150;
            let __t281 = __t233 * __t150;
            let __t481 = __t476 * __v4;
            let __t482 = __t480 * __v5;
            let __t493 = __t488 * __v4;
            let __t494 = __t492 * __v5;
            let __t504 = __t499 * __v4;
            let __t505 = __t503 * __v5;
            let __t512 = __t511 * __v5;
            let __t513 = __t488 * __v3;
            let __t520 = __t519 * __v5;
            let __t521 = __t499 * __v3;
            let __t524 = __t503 * __v3;
            let __t525 = __t519 * __v4;
            let __t458 = __t457 * __v3;
            let __t459 = __t457 * __v4;
            let __t460 = __t457 * __v5;
            let __t239 = __v7 - __t237;
            let __t242 = __v8 - __t240;
            let __t245 = __v9 - __t243;
            let __t263 = __v10 - __t261;
            let __t266 = __v11 - __t264;
            let __t283 = __v12 - __t281;
            let __t484 = __t481 - __t482;
            let __t496 = __t493 - __t494;
            let __t507 = __t504 - __t505;
            let __t515 = __t512 - __t513;
            let __t523 = __t520 - __t521;
            let __t527 = __t524 - __t525;
            let __t461 = -__t458;
            let __t462 = -__t459;
            let __t463 = -__t460;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t239,
                    __t242,
                    __t245,
                    __t242,
                    __t263,
                    __t266,
                    __t245,
                    __t266,
                    __t283,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t463,
                    __t459,
                    __t460,
                    0f64,
                    __t461,
                    __t462,
                    __t458,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t484,
                    __t496,
                    __t507,
                    __t496,
                    __t515,
                    __t523,
                    __t507,
                    __t523,
                    __t527,
                ),
            }
        }
        #[inline]
        fn bundle_and_system(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> (__RouthBundle, __GyroscopicSystem) {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t138 = __v9 * __v5;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t67 = __t66 + __t65;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t186 = __v19 * __v4;
            let __t191 = __v17 * __v3;
            let __t46 = __t45 + __t44;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t187 = __v22 * __v5;
            let __t155 = __t154 + __t153;
            let __t188 = __t186 + __t53;
            let __t192 = __v23 * __v5;
            let __t193 = __t191 + __t59;
            let __t99 = __t70 + __t46;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t196 = __v18 * __v3;
            let __t159 = 1.0f64 / __t155;
            let __t197 = __v21 * __v4;
            let __t102 = __v19 * __v1;
            let __t103 = __v16 * __v0;
            let __t133 = __t99 * __v5;
            let __t110 = __v20 * __v1;
            let __t134 = __t132 + __t131;
            let __t111 = __v17 * __v0;
            let __t189 = __t188 + __t187;
            let __t194 = __t193 + __t192;
            let __t198 = __t197 + __t196;
            let __t76 = __v29 * __v28;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t135 = __t134 + __t133;
            let __t112 = __t111 + __t110;
            let __t113 = __v23 * __v2;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t190 = __t189 + __t91;
            let __t195 = __t194 + __t95;
            let __t199 = __t198 + __t65;
            let __t158 = __v6 - __t135;
            let __t100 = __t76 * __v25;
            let __t106 = __t105 + __t104;
            let __t108 = __t76 * __v26;
            let __t114 = __t113 + __t112;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t200 = __t199 + __t99;
            let __t160 = __t158 * __t159;
            let __t203 = __t140 * 2f64;
            let __t206 = __t145 * 2f64;
            let __t209 = __t150 * 2f64;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t116 = __t76 * __v27;
            let __t122 = __t121 + __t120;
            let __t210 = __t160 * __t140;
            let __t211 = __t160 * __t145;
            let __t212 = __t160 * __t150;
            let __t225 = __t203 * __t160;
            let __t227 = __t206 * __t160;
            let __t229 = __t209 * __t160;
            let __t246 = __t160 * __v7;
            let __t271 = __t160 * __v10;
            let __t213 = __t210 + __t190;
            let __t214 = __t211 + __t195;
            let __t215 = __t212 + __t200;
            let __t292 = __t160 * __v12;
            let __t123 = __t122 - __t116;
            let __t226 = __t225 + __t190;
            let __t228 = __t227 + __t195;
            let __t230 = __t229 + __t200;
            let __t219 = __t213 * __t160;
            let __t221 = __t214 * __t160;
            let __t223 = __t215 * __t160;
            let __t247 = __t246 + __v16;
            let __t251 = __t160 * __v8;
            let __t256 = __t160 * __v9;
            let __t272 = __t271 + __v20;
            let __t276 = __t160 * __v11;
            let __t220 = __t219 + __t107;
            let __t222 = __t221 + __t115;
            let __t293 = __t292 + __v24;
            let __t224 = __t223 + __t123;
            let __t234 = __t226 * __t159;
            let __t235 = __t228 * __t159;
            let __t236 = __t230 * __t159;
            let __t252 = __t251 + __v17;
            let __t257 = __t256 + __v18;
            let __t277 = __t276 + __v21;
            let __t298 = __t247 + __v16;
            let __t316 = __t272 + __v20;
            let __t328 = __t293 + __v24;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t167 = __t91 + __t68;
            let __t168 = __t95 + __t69;
            let __t300 = __t234 * __t226;
            let __t299 = __t298 * __t160;
            let __t304 = __t252 + __v19;
            let __t310 = __t257 + __v22;
            let __t317 = __t316 * __t160;
            let __t318 = __t235 * __t228;
            let __t322 = __t277 + __v23;
            let __t329 = __t328 * __t160;
            let __t330 = __t236 * __t230;
            let __t233 = __t159 * __t150;
            let __t248 = __t231 * __t226;
            let __t273 = __t232 * __t228;
            let __t169 = __t99 + __t70;
            let __t170 = __t167 * __v0;
            let __t171 = __t168 * __v1;
            let __t302 = __t299 - __t300;
            let __t305 = __t304 * __t160;
            let __t306 = __t234 * __t228;
            let __t311 = __t310 * __t160;
            let __t312 = __t234 * __t230;
            let __t320 = __t317 - __t318;
            let __t323 = __t322 * __t160;
            let __t324 = __t235 * __t230;
            let __t332 = __t329 - __t330;
            let __t250 = __t247 - __t248;
            let __t275 = __t272 - __t273;
            let __t294 = __t233 * __t230;
            let __t172 = __t169 * __v2;
            let __t173 = __t171 + __t170;
            let __t308 = __t305 - __t306;
            let __t314 = __t311 - __t312;
            let __t326 = __t323 - __t324;
            let __t162 = __t160 * __t158;
            let __t178 = __t100 * __v3;
            let __t296 = __t293 - __t294;
            let __t179 = __t108 * __v4;
            let __t174 = __t173 + __t172;
            let __t180 = __t116 * __v5;
            let __t237 = __t231 * __t140;
            let __t240 = __t231 * __t145;
            let __t243 = __t231 * __t150;
            let __t253 = __t231 * __t228;
            let __t258 = __t231 * __t230;
            let __t181 = __t179 + __t178;
            let __t176 = __t174 - __t162;
            let __t261 = __t232 * __t145;
            let __t264 = __t232 * __t150;
            let __t267 = __t251 + __v19;
            let __t268 = __t232 * __t226;
            let __t278 = __t232 * __t230;
            let __t281 = __t233 * __t150;
            let __t182 = __t181 + __t180;
            let __t177 = __t176 * 0.5f64;
            let __t284 = __t256 + __v22;
            let __t285 = __t233 * __t226;
            let __t288 = __t276 + __v23;
            let __t289 = __t233 * __t228;
            let __t216 = __t210 + __t91;
            let __t217 = __t211 + __t95;
            let __t218 = __t212 + __t99;
            let __t185 = __t177 - __t182;
            let __t239 = __v7 - __t237;
            let __t242 = __v8 - __t240;
            let __t245 = __v9 - __t243;
            let __t255 = __t252 - __t253;
            let __t260 = __t257 - __t258;
            let __t263 = __v10 - __t261;
            let __t266 = __v11 - __t264;
            let __t270 = __t267 - __t268;
            let __t280 = __t277 - __t278;
            let __t283 = __v12 - __t281;
            let __t287 = __t284 - __t285;
            let __t291 = __t288 - __t289;
            let __t333 = -__t160;
            let __bundle = __RouthBundle {
                routhian: __t185,
                psi_dot: __t160,
                dr_domega: __Vector3::new(__t216, __t217, __t218),
                dr_dgamma: __Vector3::new(__t220, __t222, __t224),
                dr_dp: __t333,
                d2r_domega2: __Matrix3::new(
                    __t239,
                    __t242,
                    __t245,
                    __t242,
                    __t263,
                    __t266,
                    __t245,
                    __t266,
                    __t283,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t250,
                    __t255,
                    __t260,
                    __t270,
                    __t275,
                    __t280,
                    __t287,
                    __t291,
                    __t296,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t302,
                    __t308,
                    __t314,
                    __t308,
                    __t320,
                    __t326,
                    __t314,
                    __t326,
                    __t332,
                ),
            };
            let __t537 = __t220 * __v3;
            let __t538 = __t222 * __v4;
            let __t539 = __t224 * __v5;
            let __t528 = __t275 + __t250;
            let __t546 = __t326 * __v5;
            let __t551 = __t326 * __v4;
            let __t559 = __t314 * __v5;
            let __t562 = __t326 * __v3;
            let __t563 = __t308 * __v5;
            let __t540 = __t538 + __t537;
            let __t570 = __t314 * __v4;
            let __t573 = __t308 * __v4;
            let __t581 = __t314 * __v3;
            let __t590 = __t308 * __v3;
            let __t529 = __t528 + __t296;
            let __t565 = __t562 - __t563;
            let __t541 = __t540 + __t539;
            let __t572 = __t570 - __t562;
            let __t530 = __t529 * 0.5f64;
            let __t567 = __t565 * __v5;
            let __t543 = __t302 - __t541;
            let __t544 = __t320 - __t541;
            let __t545 = __t332 - __t541;
            let __t577 = __t572 * __v4;
            let __t594 = __t572 * __v3;
            let __t531 = __t530 * __v3;
            let __t532 = __t530 * __v4;
            let __t533 = __t530 * __v5;
            let __t582 = __t543 * __v5;
            let __t550 = __t544 * __v5;
            let __t547 = __t545 * __v4;
            let __t558 = __t545 * __v3;
            let __t574 = __t544 * __v3;
            let __t589 = __t543 * __v4;
            let __t534 = -__t531;
            let __t535 = -__t532;
            let __t584 = __t581 - __t582;
            let __t553 = __t550 - __t551;
            let __t549 = __t546 - __t547;
            let __t561 = __t558 - __t559;
            let __t576 = __t573 - __t574;
            let __t592 = __t589 - __t590;
            let __t536 = -__t533;
            let __t585 = __t584 * __v5;
            let __t555 = __t553 * __v5;
            let __t554 = __t549 * __v4;
            let __t566 = __t561 * __v4;
            let __t578 = __t576 * __v5;
            let __t586 = __t561 * __v3;
            let __t593 = __t592 * __v5;
            let __t597 = __t576 * __v3;
            let __t598 = __t592 * __v4;
            let __t557 = __t554 - __t555;
            let __t569 = __t566 - __t567;
            let __t580 = __t577 - __t578;
            let __t588 = __t585 - __t586;
            let __t596 = __t593 - __t594;
            let __t600 = __t597 - __t598;
            (
                __bundle,
                __GyroscopicSystem {
                    a: __Matrix3::new(
                        __t239,
                        __t242,
                        __t245,
                        __t242,
                        __t263,
                        __t266,
                        __t245,
                        __t266,
                        __t283,
                    ),
                    g: __Matrix3::new(
                        0f64,
                        __t536,
                        __t532,
                        __t533,
                        0f64,
                        __t534,
                        __t535,
                        __t531,
                        0f64,
                    ),
                    c: __Matrix3::new(
                        __t557,
                        __t569,
                        __t580,
                        __t569,
                        __t588,
                        __t596,
                        __t580,
                        __t596,
                        __t600,
                    ),
                },
            )
        }
        #[inline]
        fn reduced_equations(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __ReducedEquations {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.inertia[(0usize, 0usize)];
            let __v8: __F64 = self.inertia[(0usize, 1usize)];
            let __v9: __F64 = self.inertia[(0usize, 2usize)];
            let __v10: __F64 = self.inertia[(1usize, 1usize)];
            let __v11: __F64 = self.inertia[(1usize, 2usize)];
            let __v12: __F64 = self.inertia[(2usize, 2usize)];
            let __v13: __F64 = self.rotor[0usize];
            let __v14: __F64 = self.rotor[1usize];
            let __v15: __F64 = self.rotor[2usize];
            let __v16: __F64 = self.coupling[(0usize, 0usize)];
            let __v17: __F64 = self.coupling[(0usize, 1usize)];
            let __v18: __F64 = self.coupling[(0usize, 2usize)];
            let __v19: __F64 = self.coupling[(1usize, 0usize)];
            let __v20: __F64 = self.coupling[(1usize, 1usize)];
            let __v21: __F64 = self.coupling[(1usize, 2usize)];
            let __v22: __F64 = self.coupling[(2usize, 0usize)];
            let __v23: __F64 = self.coupling[(2usize, 1usize)];
            let __v24: __F64 = self.coupling[(2usize, 2usize)];
            let __v25: __F64 = self.com[0usize];
            let __v26: __F64 = self.com[1usize];
            let __v27: __F64 = self.com[2usize];
            let __v28: __F64 = self.mass;
            let __v29: __F64 = self.g;
            let __t136 = __v7 * __v3;
            let __t137 = __v8 * __v4;
            let __t141 = __v8 * __v3;
            let __t142 = __v10 * __v4;
            let __t53 = __v16 * __v3;
            let __t54 = __v17 * __v4;
            let __t58 = __v19 * __v3;
            let __t59 = __v20 * __v4;
            let __t138 = __v9 * __v5;
            let __t139 = __t137 + __t136;
            let __t143 = __v11 * __v5;
            let __t144 = __t142 + __t141;
            let __t146 = __v9 * __v3;
            let __t147 = __v11 * __v4;
            let __t32 = __v7 * __v0;
            let __t33 = __v8 * __v1;
            let __t37 = __v8 * __v0;
            let __t38 = __v10 * __v1;
            let __t55 = __v18 * __v5;
            let __t56 = __t54 + __t53;
            let __t60 = __v21 * __v5;
            let __t61 = __t59 + __t58;
            let __t63 = __v22 * __v3;
            let __t64 = __v23 * __v4;
            let __t140 = __t139 + __t138;
            let __t145 = __t144 + __t143;
            let __t148 = __v12 * __v5;
            let __t149 = __t147 + __t146;
            let __t34 = __v9 * __v2;
            let __t35 = __t33 + __t32;
            let __t39 = __v11 * __v2;
            let __t40 = __t38 + __t37;
            let __t42 = __v9 * __v0;
            let __t43 = __v11 * __v1;
            let __t57 = __t56 + __t55;
            let __t62 = __t61 + __t60;
            let __t65 = __v24 * __v5;
            let __t66 = __t64 + __t63;
            let __t150 = __t149 + __t148;
            let __t151 = __t140 * __v3;
            let __t152 = __t145 * __v4;
            let __t36 = __t35 + __t34;
            let __t41 = __t40 + __t39;
            let __t44 = __v12 * __v2;
            let __t45 = __t43 + __t42;
            let __t67 = __t66 + __t65;
            let __t68 = __t57 + __v13;
            let __t69 = __t62 + __v14;
            let __t153 = __t150 * __v5;
            let __t154 = __t152 + __t151;
            let __t186 = __v19 * __v4;
            let __t191 = __v17 * __v3;
            let __t46 = __t45 + __t44;
            let __t70 = __t67 + __v15;
            let __t91 = __t68 + __t36;
            let __t95 = __t69 + __t41;
            let __t196 = __v18 * __v3;
            let __t155 = __t154 + __t153;
            let __t197 = __v21 * __v4;
            let __t187 = __v22 * __v5;
            let __t188 = __t186 + __t53;
            let __t99 = __t70 + __t46;
            let __t131 = __t91 * __v3;
            let __t132 = __t95 * __v4;
            let __t192 = __v23 * __v5;
            let __t159 = 1.0f64 / __t155;
            let __t193 = __t191 + __t59;
            let __t198 = __t197 + __t196;
            let __t102 = __v19 * __v1;
            let __t133 = __t99 * __v5;
            let __t103 = __v16 * __v0;
            let __t134 = __t132 + __t131;
            let __t110 = __v20 * __v1;
            let __t111 = __v17 * __v0;
            let __t118 = __v21 * __v1;
            let __t119 = __v18 * __v0;
            let __t189 = __t188 + __t187;
            let __t194 = __t193 + __t192;
            let __t199 = __t198 + __t65;
            let __t135 = __t134 + __t133;
            let __t203 = __t140 * 2f64;
            let __t206 = __t145 * 2f64;
            let __t76 = __v29 * __v28;
            let __t104 = __t103 + __t102;
            let __t105 = __v22 * __v2;
            let __t112 = __t111 + __t110;
            let __t113 = __v23 * __v2;
            let __t158 = __v6 - __t135;
            let __t120 = __t119 + __t118;
            let __t121 = __v24 * __v2;
            let __t190 = __t189 + __t91;
            let __t195 = __t194 + __t95;
            let __t200 = __t199 + __t99;
            let __t209 = __t150 * 2f64;
            let __t100 = __t76 * __v25;
            let __t160 = __t158 * __t159;
            let __t106 = __t105 + __t104;
            let __t108 = __t76 * __v26;
            let __t114 = __t113 + __t112;
            let __t116 = __t76 * __v27;
            let __t122 = __t121 + __t120;
            let __t231 = __t159 * __t140;
            let __t232 = __t159 * __t145;
            let __t210 = __t160 * __t140;
            let __t211 = __t160 * __t145;
            let __t212 = __t160 * __t150;
            let __t225 = __t160 * __t203;
            let __t227 = __t160 * __t206;
            let __t229 = __t160 * __t209;
            let __t233 = __t159 * __t150;
            let __t246 = __t160 * __v7;
            let __t213 = __t210 + __t190;
            let __t214 = __t211 + __t195;
            let __t215 = __t212 + __t200;
            let __t226 = __t225 + __t190;
            let __t228 = __t227 + __t195;
            let __t251 = __t160 * __v8;
            let __t256 = __t160 * __v9;
            let __t271 = __t160 * __v10;
            let __t276 = __t160 * __v11;
            let __t107 = __t106 - __t100;
            let __t115 = __t114 - __t108;
            let __t123 = __t122 - __t116;
            let __t219 = __t213 * __t160;
            let __t221 = __t214 * __t160;
            let __t223 = __t215 * __t160;
            let __t230 = __t229 + __t200;
            let __t247 = __t246 + __v16;
            let __t248 = __t226 * __t231;
            let __t252 = __t251 + __v17;
            let __t253 = __t228 * __t231;
            let __t267 = __t251 + __v19;
            let __t268 = __t226 * __t232;
            let __t272 = __t271 + __v20;
            let __t273 = __t228 * __t232;
            let __t284 = __t256 + __v22;
            let __t285 = __t226 * __t233;
            let __t288 = __t276 + __v23;
            let __t289 = __t228 * __t233;
            let __t292 = __t160 * __v12;
            let __t1414 = __v4 * __v2;
            let __t1415 = __v5 * __v1;
            let __t1418 = __v5 * __v0;
            let __t1419 = __v3 * __v2;
            let __t216 = __t210 + __t91;
            let __t217 = __t211 + __t95;
            let __t218 = __t212 + __t99;
            let __t220 = __t219 + __t107;
            let __t222 = __t221 + __t115;
            let __t224 = __t223 + __t123;
            let __t250 = __t247 - __t248;
            let __t255 = __t252 - __t253;
            let __t257 = __t256 + __v18;
            let __t258 = __t230 * __t231;
            let __t270 = __t267 - __t268;
            let __t275 = __t272 - __t273;
            let __t277 = __t276 + __v21;
            let __t278 = __t230 * __t232;
            let __t287 = __t284 - __t285;
            let __t291 = __t288 - __t289;
            let __t293 = __t292 + __v24;
            let __t294 = __t230 * __t233;
            let __t1417 = __t1414 - __t1415;
            let __t1421 = __t1418 - __t1419;
            let __t1422 = __v3 * __v1;
            let __t1423 = __v4 * __v0;
            let __t260 = __t257 - __t258;
            let __t280 = __t277 - __t278;
            let __t1489 = __t217 * __v2;
            let __t296 = __t293 - __t294;
            let __t1474 = __t1417 * __t250;
            let __t1475 = __t1421 * __t255;
            let __t1479 = __t1417 * __t270;
            let __t1425 = __t1422 - __t1423;
            let __t1480 = __t1421 * __t275;
            let __t1484 = __t1417 * __t287;
            let __t1485 = __t1421 * __t291;
            let __t1490 = __t218 * __v1;
            let __t1493 = __t218 * __v0;
            let __t1494 = __t216 * __v2;
            let __t1497 = __t216 * __v1;
            let __t1498 = __t217 * __v0;
            let __t1501 = __t222 * __v5;
            let __t1502 = __t224 * __v4;
            let __t1505 = __t224 * __v3;
            let __t1506 = __t220 * __v5;
            let __t1509 = __t220 * __v4;
            let __t1510 = __t222 * __v3;
            let __t1476 = __t1425 * __t260;
            let __t1477 = __t1475 + __t1474;
            let __t1481 = __t1425 * __t280;
            let __t1482 = __t1480 + __t1479;
            let __t1486 = __t1425 * __t296;
            let __t1487 = __t1485 + __t1484;
            let __t1492 = __t1489 - __t1490;
            let __t1496 = __t1493 - __t1494;
            let __t1500 = __t1497 - __t1498;
            let __t1504 = __t1501 - __t1502;
            let __t1508 = __t1505 - __t1506;
            let __t1512 = __t1509 - __t1510;
            let __t1478 = __t1477 + __t1476;
            let __t1483 = __t1482 + __t1481;
            let __t1488 = __t1487 + __t1486;
            let __t1513 = __t1504 + __t1492;
            let __t1516 = __t1508 + __t1496;
            let __t1519 = __t1512 + __t1500;
            let __t1515 = __t1513 - __t1478;
            let __t1518 = __t1516 - __t1483;
            let __t1521 = __t1519 - __t1488;
            __ReducedEquations {
                inertia: __Matrix3::new(
                    __v7,
                    __v8,
                    __v9,
                    __v8,
                    __v10,
                    __v11,
                    __v9,
                    __v11,
                    __v12,
                ),
                right_side: __Vector3::new(__t1515, __t1518, __t1521),
                psi_dot: __t160,
                rank_one: __MaybeRankOne::None,
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            static __CERTIFICATION_OPS: [__Op; 157] = [
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Param(11),
                __Op::Param(12),
                __Op::Param(13),
                __Op::Param(14),
                __Op::Param(15),
                __Op::Param(16),
                __Op::Param(17),
                __Op::Param(18),
                __Op::Param(19),
                __Op::Param(20),
                __Op::Param(21),
                __Op::Param(22),
                __Op::Mul(0, 13),
                __Op::Mul(1, 14),
                __Op::Mul(2, 15),
                __Op::Add(27, 28),
                __Op::Add(29, 30),
                __Op::Mul(0, 16),
                __Op::Mul(1, 17),
                __Op::Mul(2, 18),
                __Op::Add(32, 33),
                __Op::Add(34, 35),
                __Op::Mul(0, 19),
                __Op::Mul(1, 20),
                __Op::Mul(2, 21),
                __Op::Add(37, 38),
                __Op::Add(39, 40),
                __Op::Add(10, 31),
                __Op::Add(11, 36),
                __Op::Add(12, 41),
                __Op::Mul(25, 26),
                __Op::Const(0x4000000000000000),
                __Op::Mul(22, 45),
                __Op::Neg(47),
                __Op::Mul(23, 45),
                __Op::Neg(49),
                __Op::Mul(24, 45),
                __Op::Neg(51),
                __Op::Mul(0, 4),
                __Op::Mul(1, 5),
                __Op::Mul(2, 6),
                __Op::Add(53, 54),
                __Op::Add(55, 56),
                __Op::Mul(0, 5),
                __Op::Mul(1, 7),
                __Op::Mul(2, 8),
                __Op::Add(58, 59),
                __Op::Add(60, 61),
                __Op::Mul(0, 6),
                __Op::Mul(1, 8),
                __Op::Mul(2, 9),
                __Op::Add(63, 64),
                __Op::Add(65, 66),
                __Op::Mul(0, 57),
                __Op::Mul(1, 62),
                __Op::Mul(2, 67),
                __Op::Add(68, 69),
                __Op::Add(70, 71),
                __Op::Recip(72),
                __Op::Mul(1, 16),
                __Op::Mul(2, 19),
                __Op::Add(27, 74),
                __Op::Add(75, 76),
                __Op::Mul(0, 14),
                __Op::Mul(2, 20),
                __Op::Add(33, 78),
                __Op::Add(79, 80),
                __Op::Mul(0, 15),
                __Op::Mul(1, 18),
                __Op::Add(82, 83),
                __Op::Add(39, 84),
                __Op::Mul(46, 13),
                __Op::Add(14, 16),
                __Op::Add(15, 19),
                __Op::Mul(46, 17),
                __Op::Add(18, 20),
                __Op::Mul(46, 21),
                __Op::Mul(0, 42),
                __Op::Mul(1, 43),
                __Op::Mul(2, 44),
                __Op::Add(92, 93),
                __Op::Add(94, 95),
                __Op::Neg(96),
                __Op::Add(3, 97),
                __Op::Mul(73, 98),
                __Op::Add(42, 77),
                __Op::Add(43, 81),
                __Op::Add(44, 85),
                __Op::Mul(57, 99),
                __Op::Mul(62, 99),
                __Op::Mul(67, 99),
                __Op::Add(100, 103),
                __Op::Add(101, 104),
                __Op::Add(102, 105),
                __Op::Mul(99, 106),
                __Op::Add(48, 109),
                __Op::Mul(99, 107),
                __Op::Add(50, 111),
                __Op::Mul(99, 108),
                __Op::Add(52, 113),
                __Op::Add(103, 106),
                __Op::Add(104, 107),
                __Op::Add(105, 108),
                __Op::Mul(73, 115),
                __Op::Mul(73, 116),
                __Op::Mul(73, 117),
                __Op::Mul(4, 99),
                __Op::Mul(5, 99),
                __Op::Mul(6, 99),
                __Op::Mul(7, 99),
                __Op::Mul(8, 99),
                __Op::Mul(9, 99),
                __Op::Add(86, 121),
                __Op::Mul(99, 127),
                __Op::Mul(115, 118),
                __Op::Neg(129),
                __Op::Add(128, 130),
                __Op::Add(87, 122),
                __Op::Mul(99, 132),
                __Op::Mul(116, 118),
                __Op::Neg(134),
                __Op::Add(133, 135),
                __Op::Add(88, 123),
                __Op::Mul(99, 137),
                __Op::Mul(117, 118),
                __Op::Neg(139),
                __Op::Add(138, 140),
                __Op::Add(89, 124),
                __Op::Mul(99, 142),
                __Op::Mul(116, 119),
                __Op::Neg(144),
                __Op::Add(143, 145),
                __Op::Add(90, 125),
                __Op::Mul(99, 147),
                __Op::Mul(117, 119),
                __Op::Neg(149),
                __Op::Add(148, 150),
                __Op::Add(91, 126),
                __Op::Mul(99, 152),
                __Op::Mul(117, 120),
                __Op::Neg(154),
                __Op::Add(153, 155),
            ];
            static __CERTIFICATION_OUT: [__Output; 9] = [
                __Output {
                    name: "dr_dgamma[0]",
                    slot: 110,
                },
                __Output {
                    name: "dr_dgamma[1]",
                    slot: 112,
                },
                __Output {
                    name: "dr_dgamma[2]",
                    slot: 114,
                },
                __Output {
                    name: "d2r_dgamma2[0][0]",
                    slot: 131,
                },
                __Output {
                    name: "d2r_dgamma2[0][1]",
                    slot: 136,
                },
                __Output {
                    name: "d2r_dgamma2[0][2]",
                    slot: 141,
                },
                __Output {
                    name: "d2r_dgamma2[1][1]",
                    slot: 146,
                },
                __Output {
                    name: "d2r_dgamma2[1][2]",
                    slot: 151,
                },
                __Output {
                    name: "d2r_dgamma2[2][2]",
                    slot: 156,
                },
            ];
            static __CERTIFICATION: __Tape = __Tape::from_static(
                &__CERTIFICATION_OPS,
                &__CERTIFICATION_OUT,
                23,
            );
            __CertificationTape::new(
                    __Tape::clone(&__CERTIFICATION),
                    <[__F64]>::to_vec(
                        &[
                            self.inertia[(0usize, 0usize)],
                            self.inertia[(0usize, 1usize)],
                            self.inertia[(0usize, 2usize)],
                            self.inertia[(1usize, 1usize)],
                            self.inertia[(1usize, 2usize)],
                            self.inertia[(2usize, 2usize)],
                            self.rotor[0usize],
                            self.rotor[1usize],
                            self.rotor[2usize],
                            self.coupling[(0usize, 0usize)],
                            self.coupling[(0usize, 1usize)],
                            self.coupling[(0usize, 2usize)],
                            self.coupling[(1usize, 0usize)],
                            self.coupling[(1usize, 1usize)],
                            self.coupling[(1usize, 2usize)],
                            self.coupling[(2usize, 0usize)],
                            self.coupling[(2usize, 1usize)],
                            self.coupling[(2usize, 2usize)],
                            self.com[0usize],
                            self.com[1usize],
                            self.com[2usize],
                            self.mass,
                            self.g,
                        ],
                    ),
                )
                .ok()
        }
        #[inline]
        fn routh_tape(&self) -> __MaybeRouthianTape {
            static __ROUTHIAN_OPS: [__Op; 119] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Param(3),
                __Op::Param(4),
                __Op::Param(5),
                __Op::Param(6),
                __Op::Param(7),
                __Op::Param(8),
                __Op::Param(9),
                __Op::Param(10),
                __Op::Param(11),
                __Op::Param(12),
                __Op::Param(13),
                __Op::Param(14),
                __Op::Param(15),
                __Op::Param(16),
                __Op::Param(17),
                __Op::Param(18),
                __Op::Param(19),
                __Op::Param(20),
                __Op::Param(21),
                __Op::Param(22),
                __Op::Const(0x3fe0000000000000),
                __Op::Mul(0, 7),
                __Op::Mul(1, 8),
                __Op::Mul(2, 9),
                __Op::Add(31, 32),
                __Op::Add(33, 34),
                __Op::Mul(0, 8),
                __Op::Mul(1, 10),
                __Op::Mul(2, 11),
                __Op::Add(36, 37),
                __Op::Add(38, 39),
                __Op::Mul(0, 9),
                __Op::Mul(1, 11),
                __Op::Mul(2, 12),
                __Op::Add(41, 42),
                __Op::Add(43, 44),
                __Op::Mul(3, 16),
                __Op::Mul(4, 17),
                __Op::Mul(5, 18),
                __Op::Add(46, 47),
                __Op::Add(48, 49),
                __Op::Mul(3, 19),
                __Op::Mul(4, 20),
                __Op::Mul(5, 21),
                __Op::Add(51, 52),
                __Op::Add(53, 54),
                __Op::Mul(3, 22),
                __Op::Mul(4, 23),
                __Op::Mul(5, 24),
                __Op::Add(56, 57),
                __Op::Add(58, 59),
                __Op::Add(13, 50),
                __Op::Add(14, 55),
                __Op::Add(15, 60),
                __Op::Mul(28, 29),
                __Op::Add(35, 61),
                __Op::Add(40, 62),
                __Op::Add(45, 63),
                __Op::Mul(25, 64),
                __Op::Mul(26, 64),
                __Op::Mul(27, 64),
                __Op::Mul(3, 65),
                __Op::Mul(4, 66),
                __Op::Mul(5, 67),
                __Op::Add(71, 72),
                __Op::Add(73, 74),
                __Op::Mul(3, 7),
                __Op::Mul(4, 8),
                __Op::Mul(5, 9),
                __Op::Add(76, 77),
                __Op::Add(78, 79),
                __Op::Mul(3, 8),
                __Op::Mul(4, 10),
                __Op::Mul(5, 11),
                __Op::Add(81, 82),
                __Op::Add(83, 84),
                __Op::Mul(3, 9),
                __Op::Mul(4, 11),
                __Op::Mul(5, 12),
                __Op::Add(86, 87),
                __Op::Add(88, 89),
                __Op::Mul(3, 80),
                __Op::Mul(4, 85),
                __Op::Mul(5, 90),
                __Op::Add(91, 92),
                __Op::Add(93, 94),
                __Op::Neg(75),
                __Op::Add(6, 96),
                __Op::Recip(95),
                __Op::Mul(97, 98),
                __Op::Mul(97, 99),
                __Op::Add(61, 65),
                __Op::Add(62, 66),
                __Op::Add(63, 67),
                __Op::Mul(0, 101),
                __Op::Mul(1, 102),
                __Op::Mul(2, 103),
                __Op::Add(104, 105),
                __Op::Add(106, 107),
                __Op::Neg(100),
                __Op::Add(108, 109),
                __Op::Mul(30, 110),
                __Op::Mul(3, 68),
                __Op::Mul(4, 69),
                __Op::Mul(5, 70),
                __Op::Add(112, 113),
                __Op::Add(114, 115),
                __Op::Neg(116),
                __Op::Add(111, 117),
            ];
            static __ROUTHIAN_OUT: [__Output; 1] = [
                __Output {
                    name: "routhian",
                    slot: 118,
                },
            ];
            static __ROUTHIAN: __Tape = __Tape::from_static(
                &__ROUTHIAN_OPS,
                &__ROUTHIAN_OUT,
                23,
            );
            __RouthianTape::new(
                    __Tape::clone(&__ROUTHIAN),
                    <[__F64]>::to_vec(
                        &[
                            self.inertia[(0usize, 0usize)],
                            self.inertia[(0usize, 1usize)],
                            self.inertia[(0usize, 2usize)],
                            self.inertia[(1usize, 1usize)],
                            self.inertia[(1usize, 2usize)],
                            self.inertia[(2usize, 2usize)],
                            self.rotor[0usize],
                            self.rotor[1usize],
                            self.rotor[2usize],
                            self.coupling[(0usize, 0usize)],
                            self.coupling[(0usize, 1usize)],
                            self.coupling[(0usize, 2usize)],
                            self.coupling[(1usize, 0usize)],
                            self.coupling[(1usize, 1usize)],
                            self.coupling[(1usize, 2usize)],
                            self.coupling[(2usize, 0usize)],
                            self.coupling[(2usize, 1usize)],
                            self.coupling[(2usize, 2usize)],
                            self.com[0usize],
                            self.com[1usize],
                            self.com[2usize],
                            self.mass,
                            self.g,
                        ],
                    ),
                )
                .ok()
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for Gyrostat {
        const LAGRANGIAN: &'static str = "0.5·(ω₃·(ω₃·inertia[(2,2)] + ω₁·inertia[(0,2)] + ω₂·inertia[(1,2)]) + ω₁·(ω₃·inertia[(0,2)] + ω₁·inertia[(0,0)] + ω₂·inertia[(0,1)]) + ω₂·(ω₃·inertia[(1,2)] + ω₁·inertia[(0,1)] + ω₂·inertia[(1,1)])) + ω₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + ω₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + ω₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]) - mass·g·(γ₃·com[2] + γ₁·com[0] + γ₂·com[1])";
        const AMENDED_POTENTIAL: &'static str = "(γ₃·com[2]·mass·g + γ₁·com[0]·mass·g + γ₂·com[1]·mass·g) + 0.5·(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)])))^2 / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
        const PSI_DOT_AT_REST: &'static str = "(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]))) / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
        fn latex(&self) -> ::routh::__private::LatexFormulas {
            static __LATEX: ::routh::__private::DerivedLatex = ::routh::__private::DerivedLatex::new(
                "# [lagrangian (kinetic = 0.5 * omega . dot (inertia * omega) , linear = (rotor + coupling * gamma) . dot (omega) , potential = mass * g * com . dot (gamma) ,)] pub struct Gyrostat { # [lagrangian (symmetric)] pub inertia : Matrix3 < f64 > , pub rotor : Vector3 < f64 > , pub coupling : Matrix3 < f64 > , pub com : Vector3 < f64 > , pub mass : f64 , pub g : f64 , }",
            );
            __LATEX.get()
        }
    }
};
