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
    type __RouthTape = ::routh::__private::RouthTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t47 = __v0 * __t36;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t48 = __v1 * __t41;
            let __t50 = __t47 + __t48;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t49 = __v2 * __t46;
            let __t51 = __t49 + __t50;
            let __t52 = 0.5f64 * __t51;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t71 = __v0 * __t68;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t72 = __v1 * __t69;
            let __t74 = __t71 + __t72;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t73 = __v2 * __t70;
            let __t75 = __t73 + __t74;
            let __t76 = __v28 * __v29;
            let __t77 = __v3 * __v25;
            let __t78 = __v4 * __v26;
            let __t80 = __t77 + __t78;
            let __t79 = __v5 * __v27;
            let __t81 = __t79 + __t80;
            let __t82 = __t76 * __t81;
            let __t84 = __t75 - __t82;
            let __t85 = __t52 + __t84;
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
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
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t108 = __v26 * __t76;
            let __t116 = __v27 * __t76;
            let __t102 = __v1 * __v19;
            let __t103 = __v0 * __v16;
            let __t104 = __t102 + __t103;
            let __t105 = __v2 * __v22;
            let __t106 = __t104 + __t105;
            let __t107 = __t106 - __t100;
            let __t110 = __v1 * __v20;
            let __t111 = __v0 * __v17;
            let __t112 = __t110 + __t111;
            let __t113 = __v2 * __v23;
            let __t114 = __t112 + __t113;
            let __t115 = __t114 - __t108;
            let __t118 = __v1 * __v21;
            let __t119 = __v0 * __v18;
            let __t120 = __t118 + __t119;
            let __t121 = __v2 * __v24;
            let __t122 = __t120 + __t121;
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t47 = __v0 * __t36;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t48 = __v1 * __t41;
            let __t50 = __t47 + __t48;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t49 = __v2 * __t46;
            let __t51 = __t49 + __t50;
            let __t52 = 0.5f64 * __t51;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t71 = __v0 * __t68;
            let __t91 = __t36 + __t68;
            let __t124 = __v0 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t72 = __v1 * __t69;
            let __t74 = __t71 + __t72;
            let __t95 = __t41 + __t69;
            let __t125 = __v1 * __t95;
            let __t127 = __t124 + __t125;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t73 = __v2 * __t70;
            let __t75 = __t73 + __t74;
            let __t99 = __t46 + __t70;
            let __t126 = __v2 * __t99;
            let __t128 = __t126 + __t127;
            let __t76 = __v28 * __v29;
            let __t77 = __v3 * __v25;
            let __t78 = __v4 * __v26;
            let __t80 = __t77 + __t78;
            let __t79 = __v5 * __v27;
            let __t81 = __t79 + __t80;
            let __t82 = __t76 * __t81;
            let __t84 = __t75 - __t82;
            let __t85 = __t52 + __t84;
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            __t135
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t315 = __t68 + __t91;
            let __t318 = __v0 * __t315;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t316 = __t69 + __t95;
            let __t319 = __v1 * __t316;
            let __t321 = __t318 + __t319;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t317 = __t70 + __t99;
            let __t320 = __v2 * __t317;
            let __t322 = __t320 + __t321;
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t326 = __v3 * __t100;
            let __t108 = __v26 * __t76;
            let __t327 = __v4 * __t108;
            let __t329 = __t326 + __t327;
            let __t116 = __v27 * __t76;
            let __t328 = __v5 * __t116;
            let __t330 = __t328 + __t329;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t162 = __t158 * __t160;
            let __t324 = __t322 - __t162;
            let __t325 = 0.5f64 * __t324;
            let __t333 = __t325 - __t330;
            __t333
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t191 = __t140 * __t160;
            let __t197 = __t91 + __t191;
            let __t192 = __t145 * __t160;
            let __t198 = __t95 + __t192;
            let __t193 = __t150 * __t160;
            let __t199 = __t99 + __t193;
            __Vector3::new(__t197, __t198, __t199)
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t108 = __v26 * __t76;
            let __t116 = __v27 * __t76;
            let __t102 = __v1 * __v19;
            let __t103 = __v0 * __v16;
            let __t104 = __t102 + __t103;
            let __t105 = __v2 * __v22;
            let __t106 = __t104 + __t105;
            let __t107 = __t106 - __t100;
            let __t110 = __v1 * __v20;
            let __t111 = __v0 * __v17;
            let __t112 = __t110 + __t111;
            let __t113 = __v2 * __v23;
            let __t114 = __t112 + __t113;
            let __t115 = __t114 - __t108;
            let __t118 = __v1 * __v21;
            let __t119 = __v0 * __v18;
            let __t120 = __t118 + __t119;
            let __t121 = __v2 * __v24;
            let __t122 = __t120 + __t121;
            let __t123 = __t122 - __t116;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t191 = __t140 * __t160;
            let __t192 = __t145 * __t160;
            let __t193 = __t150 * __t160;
            let __t167 = __v4 * __v19;
            let __t169 = __t53 + __t167;
            let __t168 = __v5 * __v22;
            let __t170 = __t168 + __t169;
            let __t171 = __t91 + __t170;
            let __t194 = __t171 + __t191;
            let __t200 = __t160 * __t194;
            let __t201 = __t107 + __t200;
            let __t172 = __v3 * __v17;
            let __t174 = __t59 + __t172;
            let __t173 = __v5 * __v23;
            let __t175 = __t173 + __t174;
            let __t176 = __t95 + __t175;
            let __t195 = __t176 + __t192;
            let __t202 = __t160 * __t195;
            let __t203 = __t115 + __t202;
            let __t177 = __v3 * __v18;
            let __t178 = __v4 * __v21;
            let __t179 = __t177 + __t178;
            let __t180 = __t65 + __t179;
            let __t181 = __t99 + __t180;
            let __t196 = __t181 + __t193;
            let __t204 = __t160 * __t196;
            let __t205 = __t123 + __t204;
            __Vector3::new(__t201, __t203, __t205)
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t160 = __t158 / __t155;
            let __t314 = -__t160;
            __t314
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
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t159 = 1.0f64 / __t155;
            let __t212 = __t140 * __t159;
            let __t218 = __t140 * __t212;
            let __t220 = __v7 - __t218;
            let __t221 = __t145 * __t212;
            let __t223 = __v8 - __t221;
            let __t224 = __t150 * __t212;
            let __t226 = __v9 - __t224;
            let __t213 = __t145 * __t159;
            let __t242 = __t145 * __t213;
            let __t244 = __v10 - __t242;
            let __t245 = __t150 * __t213;
            let __t247 = __v11 - __t245;
            let __t214 = __t150 * __t159;
            let __t262 = __t150 * __t214;
            let __t264 = __v12 - __t262;
            __Matrix3::new(
                __t220,
                __t223,
                __t226,
                __t223,
                __t244,
                __t247,
                __t226,
                __t247,
                __t264,
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t184 = 2f64 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t187 = 2f64 * __t145;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t159 = 1.0f64 / __t155;
            let __t160 = __t158 * __t159;
            let __t206 = __t160 * __t184;
            let __t208 = __t160 * __t187;
            let __t227 = __v7 * __t160;
            let __t228 = __v16 + __t227;
            let __t232 = __v8 * __t160;
            let __t233 = __v17 + __t232;
            let __t248 = __v19 + __t232;
            let __t237 = __v9 * __t160;
            let __t238 = __v18 + __t237;
            let __t265 = __v22 + __t237;
            let __t252 = __v10 * __t160;
            let __t253 = __v20 + __t252;
            let __t257 = __v11 * __t160;
            let __t258 = __v21 + __t257;
            let __t269 = __v23 + __t257;
            let __t273 = __v12 * __t160;
            let __t274 = __v24 + __t273;
            let __t212 = __t140 * __t159;
            let __t213 = __t145 * __t159;
            let __t214 = __t150 * __t159;
            let __t190 = 2f64 * __t150;
            let __t210 = __t160 * __t190;
            let __t167 = __v4 * __v19;
            let __t169 = __t53 + __t167;
            let __t168 = __v5 * __v22;
            let __t170 = __t168 + __t169;
            let __t171 = __t91 + __t170;
            let __t207 = __t171 + __t206;
            let __t229 = __t207 * __t212;
            let __t231 = __t228 - __t229;
            let __t249 = __t207 * __t213;
            let __t251 = __t248 - __t249;
            let __t266 = __t207 * __t214;
            let __t268 = __t265 - __t266;
            let __t172 = __v3 * __v17;
            let __t174 = __t59 + __t172;
            let __t173 = __v5 * __v23;
            let __t175 = __t173 + __t174;
            let __t176 = __t95 + __t175;
            let __t209 = __t176 + __t208;
            let __t234 = __t209 * __t212;
            let __t236 = __t233 - __t234;
            let __t254 = __t209 * __t213;
            let __t256 = __t253 - __t254;
            let __t270 = __t209 * __t214;
            let __t272 = __t269 - __t270;
            let __t177 = __v3 * __v18;
            let __t178 = __v4 * __v21;
            let __t179 = __t177 + __t178;
            let __t180 = __t65 + __t179;
            let __t181 = __t99 + __t180;
            let __t211 = __t181 + __t210;
            let __t239 = __t211 * __t212;
            let __t241 = __t238 - __t239;
            let __t259 = __t211 * __t213;
            let __t261 = __t258 - __t259;
            let __t275 = __t211 * __t214;
            let __t277 = __t274 - __t275;
            __Matrix3::new(
                __t231,
                __t236,
                __t241,
                __t251,
                __t256,
                __t261,
                __t268,
                __t272,
                __t277,
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t184 = 2f64 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t187 = 2f64 * __t145;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t159 = 1.0f64 / __t155;
            let __t160 = __t158 * __t159;
            let __t206 = __t160 * __t184;
            let __t208 = __t160 * __t187;
            let __t227 = __v7 * __t160;
            let __t228 = __v16 + __t227;
            let __t279 = __v16 + __t228;
            let __t280 = __t160 * __t279;
            let __t232 = __v8 * __t160;
            let __t233 = __v17 + __t232;
            let __t285 = __v19 + __t233;
            let __t286 = __t160 * __t285;
            let __t237 = __v9 * __t160;
            let __t238 = __v18 + __t237;
            let __t291 = __v22 + __t238;
            let __t292 = __t160 * __t291;
            let __t252 = __v10 * __t160;
            let __t253 = __v20 + __t252;
            let __t297 = __v20 + __t253;
            let __t298 = __t160 * __t297;
            let __t257 = __v11 * __t160;
            let __t258 = __v21 + __t257;
            let __t303 = __v23 + __t258;
            let __t304 = __t160 * __t303;
            let __t273 = __v12 * __t160;
            let __t274 = __v24 + __t273;
            let __t309 = __v24 + __t274;
            let __t310 = __t160 * __t309;
            let __t190 = 2f64 * __t150;
            let __t210 = __t160 * __t190;
            let __t167 = __v4 * __v19;
            let __t169 = __t53 + __t167;
            let __t168 = __v5 * __v22;
            let __t170 = __t168 + __t169;
            let __t171 = __t91 + __t170;
            let __t207 = __t171 + __t206;
            let __t215 = __t159 * __t207;
            let __t281 = __t207 * __t215;
            let __t283 = __t280 - __t281;
            let __t172 = __v3 * __v17;
            let __t174 = __t59 + __t172;
            let __t173 = __v5 * __v23;
            let __t175 = __t173 + __t174;
            let __t176 = __t95 + __t175;
            let __t209 = __t176 + __t208;
            let __t216 = __t159 * __t209;
            let __t299 = __t209 * __t216;
            let __t301 = __t298 - __t299;
            let __t287 = __t209 * __t215;
            let __t289 = __t286 - __t287;
            let __t177 = __v3 * __v18;
            let __t178 = __v4 * __v21;
            let __t179 = __t177 + __t178;
            let __t180 = __t65 + __t179;
            let __t181 = __t99 + __t180;
            let __t211 = __t181 + __t210;
            let __t217 = __t159 * __t211;
            let __t311 = __t211 * __t217;
            let __t313 = __t310 - __t311;
            let __t293 = __t211 * __t215;
            let __t295 = __t292 - __t293;
            let __t305 = __t211 * __t216;
            let __t307 = __t304 - __t305;
            __Matrix3::new(
                __t283,
                __t289,
                __t295,
                __t289,
                __t301,
                __t307,
                __t295,
                __t307,
                __t313,
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
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t334 = __v3 * __t68;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t335 = __v4 * __t69;
            let __t337 = __t334 + __t335;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t336 = __v5 * __t70;
            let __t338 = __t336 + __t337;
            let __t340 = __v6 - __t338;
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t326 = __v3 * __t100;
            let __t108 = __v26 * __t76;
            let __t327 = __v4 * __t108;
            let __t329 = __t326 + __t327;
            let __t116 = __v27 * __t76;
            let __t328 = __v5 * __t116;
            let __t330 = __t328 + __t329;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t341 = __t340 / __t155;
            let __t343 = __t340 * __t341;
            let __t345 = (-0.5f64) * __t343;
            let __t454 = __t345 - __t330;
            let __t455 = -__t454;
            __t455
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
            let __t32 = __v0 * __v7;
            let __t33 = __v1 * __v8;
            let __t35 = __t32 + __t33;
            let __t34 = __v2 * __v9;
            let __t36 = __t34 + __t35;
            let __t37 = __v0 * __v8;
            let __t38 = __v1 * __v10;
            let __t40 = __t37 + __t38;
            let __t39 = __v2 * __v11;
            let __t41 = __t39 + __t40;
            let __t42 = __v0 * __v9;
            let __t43 = __v1 * __v11;
            let __t45 = __t42 + __t43;
            let __t44 = __v2 * __v12;
            let __t46 = __t44 + __t45;
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t91 = __t36 + __t68;
            let __t131 = __v3 * __t91;
            let __t315 = __t68 + __t91;
            let __t318 = __v0 * __t315;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t95 = __t41 + __t69;
            let __t132 = __v4 * __t95;
            let __t134 = __t131 + __t132;
            let __t316 = __t69 + __t95;
            let __t319 = __v1 * __t316;
            let __t321 = __t318 + __t319;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t99 = __t46 + __t70;
            let __t133 = __v5 * __t99;
            let __t135 = __t133 + __t134;
            let __t158 = __v6 - __t135;
            let __t317 = __t70 + __t99;
            let __t320 = __v2 * __t317;
            let __t322 = __t320 + __t321;
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t326 = __v3 * __t100;
            let __t108 = __v26 * __t76;
            let __t327 = __v4 * __t108;
            let __t329 = __t326 + __t327;
            let __t116 = __v27 * __t76;
            let __t328 = __v5 * __t116;
            let __t330 = __t328 + __t329;
            let __t102 = __v1 * __v19;
            let __t103 = __v0 * __v16;
            let __t104 = __t102 + __t103;
            let __t105 = __v2 * __v22;
            let __t106 = __t104 + __t105;
            let __t107 = __t106 - __t100;
            let __t110 = __v1 * __v20;
            let __t111 = __v0 * __v17;
            let __t112 = __t110 + __t111;
            let __t113 = __v2 * __v23;
            let __t114 = __t112 + __t113;
            let __t115 = __t114 - __t108;
            let __t118 = __v1 * __v21;
            let __t119 = __v0 * __v18;
            let __t120 = __t118 + __t119;
            let __t121 = __v2 * __v24;
            let __t122 = __t120 + __t121;
            let __t123 = __t122 - __t116;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t184 = 2f64 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t187 = 2f64 * __t145;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t159 = 1.0f64 / __t155;
            let __t160 = __t158 * __t159;
            let __t162 = __t158 * __t160;
            let __t324 = __t322 - __t162;
            let __t325 = 0.5f64 * __t324;
            let __t333 = __t325 - __t330;
            let __t191 = __t140 * __t160;
            let __t197 = __t91 + __t191;
            let __t192 = __t145 * __t160;
            let __t198 = __t95 + __t192;
            let __t193 = __t150 * __t160;
            let __t199 = __t99 + __t193;
            let __t206 = __t160 * __t184;
            let __t208 = __t160 * __t187;
            let __t227 = __v7 * __t160;
            let __t228 = __v16 + __t227;
            let __t279 = __v16 + __t228;
            let __t280 = __t160 * __t279;
            let __t232 = __v8 * __t160;
            let __t233 = __v17 + __t232;
            let __t285 = __v19 + __t233;
            let __t286 = __t160 * __t285;
            let __t248 = __v19 + __t232;
            let __t237 = __v9 * __t160;
            let __t238 = __v18 + __t237;
            let __t291 = __v22 + __t238;
            let __t292 = __t160 * __t291;
            let __t265 = __v22 + __t237;
            let __t252 = __v10 * __t160;
            let __t253 = __v20 + __t252;
            let __t297 = __v20 + __t253;
            let __t298 = __t160 * __t297;
            let __t257 = __v11 * __t160;
            let __t258 = __v21 + __t257;
            let __t303 = __v23 + __t258;
            let __t304 = __t160 * __t303;
            let __t269 = __v23 + __t257;
            let __t273 = __v12 * __t160;
            let __t274 = __v24 + __t273;
            let __t309 = __v24 + __t274;
            let __t310 = __t160 * __t309;
            let __t314 = -__t160;
            let __t212 = __t140 * __t159;
            let __t218 = __t140 * __t212;
            let __t220 = __v7 - __t218;
            let __t221 = __t145 * __t212;
            let __t223 = __v8 - __t221;
            let __t224 = __t150 * __t212;
            let __t226 = __v9 - __t224;
            let __t213 = __t145 * __t159;
            let __t242 = __t145 * __t213;
            let __t244 = __v10 - __t242;
            let __t245 = __t150 * __t213;
            let __t247 = __v11 - __t245;
            let __t214 = __t150 * __t159;
            let __t262 = __t150 * __t214;
            let __t264 = __v12 - __t262;
            let __t190 = 2f64 * __t150;
            let __t210 = __t160 * __t190;
            let __t167 = __v4 * __v19;
            let __t169 = __t53 + __t167;
            let __t168 = __v5 * __v22;
            let __t170 = __t168 + __t169;
            let __t171 = __t91 + __t170;
            let __t194 = __t171 + __t191;
            let __t200 = __t160 * __t194;
            let __t201 = __t107 + __t200;
            let __t207 = __t171 + __t206;
            let __t215 = __t159 * __t207;
            let __t281 = __t207 * __t215;
            let __t283 = __t280 - __t281;
            let __t229 = __t207 * __t212;
            let __t231 = __t228 - __t229;
            let __t249 = __t207 * __t213;
            let __t251 = __t248 - __t249;
            let __t266 = __t207 * __t214;
            let __t268 = __t265 - __t266;
            let __t172 = __v3 * __v17;
            let __t174 = __t59 + __t172;
            let __t173 = __v5 * __v23;
            let __t175 = __t173 + __t174;
            let __t176 = __t95 + __t175;
            let __t195 = __t176 + __t192;
            let __t202 = __t160 * __t195;
            let __t203 = __t115 + __t202;
            let __t209 = __t176 + __t208;
            let __t216 = __t159 * __t209;
            let __t299 = __t209 * __t216;
            let __t301 = __t298 - __t299;
            let __t234 = __t209 * __t212;
            let __t236 = __t233 - __t234;
            let __t254 = __t209 * __t213;
            let __t256 = __t253 - __t254;
            let __t270 = __t209 * __t214;
            let __t272 = __t269 - __t270;
            let __t287 = __t209 * __t215;
            let __t289 = __t286 - __t287;
            let __t177 = __v3 * __v18;
            let __t178 = __v4 * __v21;
            let __t179 = __t177 + __t178;
            let __t180 = __t65 + __t179;
            let __t181 = __t99 + __t180;
            let __t196 = __t181 + __t193;
            let __t204 = __t160 * __t196;
            let __t205 = __t123 + __t204;
            let __t211 = __t181 + __t210;
            let __t217 = __t159 * __t211;
            let __t311 = __t211 * __t217;
            let __t313 = __t310 - __t311;
            let __t239 = __t211 * __t212;
            let __t241 = __t238 - __t239;
            let __t259 = __t211 * __t213;
            let __t261 = __t258 - __t259;
            let __t275 = __t211 * __t214;
            let __t277 = __t274 - __t275;
            let __t293 = __t211 * __t215;
            let __t295 = __t292 - __t293;
            let __t305 = __t211 * __t216;
            let __t307 = __t304 - __t305;
            __RouthBundle {
                routhian: __t333,
                psi_dot: __t160,
                dr_domega: __Vector3::new(__t197, __t198, __t199),
                dr_dgamma: __Vector3::new(__t201, __t203, __t205),
                dr_dp: __t314,
                d2r_domega2: __Matrix3::new(
                    __t220,
                    __t223,
                    __t226,
                    __t223,
                    __t244,
                    __t247,
                    __t226,
                    __t247,
                    __t264,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t231,
                    __t236,
                    __t241,
                    __t251,
                    __t256,
                    __t261,
                    __t268,
                    __t272,
                    __t277,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t283,
                    __t289,
                    __t295,
                    __t289,
                    __t301,
                    __t307,
                    __t295,
                    __t307,
                    __t313,
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
            let __t53 = __v3 * __v16;
            let __t54 = __v4 * __v17;
            let __t56 = __t53 + __t54;
            let __t55 = __v5 * __v18;
            let __t57 = __t55 + __t56;
            let __t68 = __v13 + __t57;
            let __t334 = __v3 * __t68;
            let __t58 = __v3 * __v19;
            let __t59 = __v4 * __v20;
            let __t61 = __t58 + __t59;
            let __t60 = __v5 * __v21;
            let __t62 = __t60 + __t61;
            let __t69 = __v14 + __t62;
            let __t335 = __v4 * __t69;
            let __t337 = __t334 + __t335;
            let __t63 = __v3 * __v22;
            let __t64 = __v4 * __v23;
            let __t66 = __t63 + __t64;
            let __t65 = __v5 * __v24;
            let __t67 = __t65 + __t66;
            let __t70 = __v15 + __t67;
            let __t336 = __v5 * __t70;
            let __t338 = __t336 + __t337;
            let __t340 = __v6 - __t338;
            let __t76 = __v28 * __v29;
            let __t100 = __v25 * __t76;
            let __t108 = __v26 * __t76;
            let __t116 = __v27 * __t76;
            let __t136 = __v3 * __v7;
            let __t137 = __v4 * __v8;
            let __t139 = __t136 + __t137;
            let __t138 = __v5 * __v9;
            let __t140 = __t138 + __t139;
            let __t151 = __v3 * __t140;
            let __t141 = __v3 * __v8;
            let __t142 = __v4 * __v10;
            let __t144 = __t141 + __t142;
            let __t143 = __v5 * __v11;
            let __t145 = __t143 + __t144;
            let __t152 = __v4 * __t145;
            let __t154 = __t151 + __t152;
            let __t146 = __v3 * __v9;
            let __t147 = __v4 * __v11;
            let __t149 = __t146 + __t147;
            let __t148 = __v5 * __v12;
            let __t150 = __t148 + __t149;
            let __t153 = __v5 * __t150;
            let __t155 = __t153 + __t154;
            let __t159 = 1.0f64 / __t155;
            let __t212 = __t140 * __t159;
            let __t218 = __t140 * __t212;
            let __t220 = __v7 - __t218;
            let __t221 = __t145 * __t212;
            let __t223 = __v8 - __t221;
            let __t224 = __t150 * __t212;
            let __t226 = __v9 - __t224;
            let __t213 = __t145 * __t159;
            let __t242 = __t145 * __t213;
            let __t244 = __v10 - __t242;
            let __t245 = __t150 * __t213;
            let __t247 = __v11 - __t245;
            let __t214 = __t150 * __t159;
            let __t262 = __t150 * __t214;
            let __t264 = __v12 - __t262;
            let __t341 = __t159 * __t340;
            let __t353 = __t140 * __t341;
            let __t354 = __t145 * __t341;
            let __t355 = __t150 * __t341;
            let __t377 = __v7 * __t341;
            let __t378 = __v16 + __t377;
            let __t382 = __v8 * __t341;
            let __t387 = __v9 * __t341;
            let __t396 = __v10 * __t341;
            let __t397 = __v20 + __t396;
            let __t401 = __v11 * __t341;
            let __t414 = __v12 * __t341;
            let __t415 = __v24 + __t414;
            let __t167 = __v4 * __v19;
            let __t169 = __t53 + __t167;
            let __t168 = __v5 * __v22;
            let __t170 = __t168 + __t169;
            let __t347 = __t68 + __t170;
            let __t356 = __t347 + __t353;
            let __t362 = __t341 * __t356;
            let __t363 = __t362 - __t100;
            let __t471 = __v3 * __t363;
            let __t369 = __t353 + __t356;
            let __t374 = __t159 * __t369;
            let __t421 = __t369 * __t374;
            let __t379 = __t212 * __t369;
            let __t381 = __t378 - __t379;
            let __t172 = __v3 * __v17;
            let __t174 = __t59 + __t172;
            let __t173 = __v5 * __v23;
            let __t175 = __t173 + __t174;
            let __t348 = __t69 + __t175;
            let __t357 = __t348 + __t354;
            let __t364 = __t341 * __t357;
            let __t365 = __t364 - __t108;
            let __t472 = __v4 * __t365;
            let __t474 = __t471 + __t472;
            let __t371 = __t354 + __t357;
            let __t375 = __t159 * __t371;
            let __t436 = __t371 * __t375;
            let __t398 = __t213 * __t371;
            let __t400 = __t397 - __t398;
            let __t459 = __t381 + __t400;
            let __t426 = __t371 * __t374;
            let __t177 = __v3 * __v18;
            let __t178 = __v4 * __v21;
            let __t179 = __t177 + __t178;
            let __t180 = __t65 + __t179;
            let __t349 = __t70 + __t180;
            let __t358 = __t349 + __t355;
            let __t366 = __t341 * __t358;
            let __t367 = __t366 - __t116;
            let __t473 = __v5 * __t367;
            let __t475 = __t473 + __t474;
            let __t373 = __t355 + __t358;
            let __t376 = __t159 * __t373;
            let __t446 = __t373 * __t376;
            let __t416 = __t214 * __t373;
            let __t418 = __t415 - __t416;
            let __t460 = __t418 + __t459;
            let __t462 = __v5 * __t460;
            let __t463 = 0.5f64 * __t462;
            let __t464 = (-0.5f64) * __t462;
            let __t465 = __v4 * __t460;
            let __t466 = 0.5f64 * __t465;
            let __t470 = (-0.5f64) * __t465;
            let __t467 = __v3 * __t460;
            let __t468 = 0.5f64 * __t467;
            let __t469 = (-0.5f64) * __t467;
            let __t431 = __t373 * __t374;
            let __t441 = __t373 * __t375;
            let __t278 = 2f64 * __v16;
            let __t419 = __t278 + __t377;
            let __t420 = __t341 * __t419;
            let __t423 = __t420 - __t421;
            let __t477 = __t475 - __t423;
            let __t500 = __v5 * __t477;
            let __t513 = __v4 * __t477;
            let __t284 = __v17 + __v19;
            let __t424 = __t284 + __t382;
            let __t425 = __t341 * __t424;
            let __t428 = __t425 - __t426;
            let __t485 = __v5 * __t428;
            let __t514 = __v3 * __t428;
            let __t516 = __t513 + __t514;
            let __t548 = __v4 * __t516;
            let __t517 = __v4 * __t428;
            let __t290 = __v18 + __v22;
            let __t429 = __t290 + __t387;
            let __t430 = __t341 * __t429;
            let __t433 = __t430 - __t431;
            let __t487 = __v4 * __t433;
            let __t489 = __t487 - __t485;
            let __t528 = __v5 * __t489;
            let __t534 = __v4 * __t489;
            let __t502 = __v3 * __t433;
            let __t504 = __t500 + __t502;
            let __t538 = __v5 * __t504;
            let __t542 = __v4 * __t504;
            let __t509 = __v5 * __t433;
            let __t296 = 2f64 * __v20;
            let __t434 = __t296 + __t396;
            let __t435 = __t341 * __t434;
            let __t438 = __t435 - __t436;
            let __t481 = __t475 - __t438;
            let __t490 = __v5 * __t481;
            let __t519 = __v3 * __t481;
            let __t521 = __t517 + __t519;
            let __t549 = __v3 * __t521;
            let __t551 = __t548 + __t549;
            let __t302 = __v21 + __v23;
            let __t439 = __t302 + __t401;
            let __t440 = __t341 * __t439;
            let __t443 = __t440 - __t441;
            let __t491 = __v4 * __t443;
            let __t493 = __t490 + __t491;
            let __t524 = __v5 * __t493;
            let __t535 = __v3 * __t493;
            let __t537 = __t534 - __t535;
            let __t494 = __v5 * __t443;
            let __t506 = __v3 * __t443;
            let __t508 = __t485 - __t506;
            let __t544 = __v3 * __t508;
            let __t546 = __t542 + __t544;
            let __t547 = -__t546;
            let __t308 = 2f64 * __v24;
            let __t444 = __t308 + __t414;
            let __t445 = __t341 * __t444;
            let __t448 = __t445 - __t446;
            let __t484 = __t475 - __t448;
            let __t496 = __v4 * __t484;
            let __t498 = __t494 + __t496;
            let __t525 = __v4 * __t498;
            let __t527 = __t524 + __t525;
            let __t530 = __v3 * __t498;
            let __t532 = __t528 + __t530;
            let __t533 = -__t532;
            let __t511 = __v3 * __t484;
            let __t512 = __t509 + __t511;
            let __t540 = __v3 * __t512;
            let __t541 = __t538 + __t540;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t220,
                    __t223,
                    __t226,
                    __t223,
                    __t244,
                    __t247,
                    __t226,
                    __t247,
                    __t264,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t464,
                    __t466,
                    __t463,
                    0f64,
                    __t469,
                    __t470,
                    __t468,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t527,
                    __t533,
                    __t537,
                    __t533,
                    __t541,
                    __t547,
                    __t537,
                    __t547,
                    __t551,
                ),
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            __RouthTape::parse(
                "g 0;g 1;g 2;p;f 0;f 1;f 2;f 3;f 4;f 5;f 6;f 7;f 8;f 9;f 10;f 11;f 12;f 13;f 14;f 15;f 16;f 17;f 18;f 19;f 20;f 21;f 22;* 0 13;* 1 14;* 2 15;+ 27 28;+ 29 30;* 0 16;* 1 17;* 2 18;+ 32 33;+ 34 35;* 0 19;* 1 20;* 2 21;+ 37 38;+ 39 40;+ 10 31;+ 11 36;+ 12 41;* 25 26;c 4000000000000000;* 22 45;- 47;* 23 45;- 49;* 24 45;- 51;* 0 4;* 1 5;* 2 6;+ 53 54;+ 55 56;* 0 5;* 1 7;* 2 8;+ 58 59;+ 60 61;* 0 6;* 1 8;* 2 9;+ 63 64;+ 65 66;* 0 57;* 1 62;* 2 67;+ 68 69;+ 70 71;/ 72;* 1 16;* 2 19;+ 27 74;+ 75 76;* 0 14;* 2 20;+ 33 78;+ 79 80;* 0 15;* 1 18;+ 82 83;+ 39 84;* 46 13;+ 14 16;+ 15 19;* 46 17;+ 18 20;* 46 21;* 0 42;* 1 43;* 2 44;+ 92 93;+ 94 95;- 96;+ 3 97;* 73 98;+ 42 77;+ 43 81;+ 44 85;* 57 99;* 62 99;* 67 99;+ 100 103;+ 101 104;+ 102 105;* 99 106;+ 48 109;* 99 107;+ 50 111;* 99 108;+ 52 113;+ 103 106;+ 104 107;+ 105 108;* 73 115;* 73 116;* 73 117;* 4 99;* 5 99;* 6 99;* 7 99;* 8 99;* 9 99;+ 86 121;* 99 127;* 115 118;- 129;+ 128 130;+ 87 122;* 99 132;* 116 118;- 134;+ 133 135;+ 88 123;* 99 137;* 117 118;- 139;+ 138 140;+ 89 124;* 99 142;* 116 119;- 144;+ 143 145;+ 90 125;* 99 147;* 117 119;- 149;+ 148 150;+ 91 126;* 99 152;* 117 120;- 154;+ 153 155;o 110 112 114 131 136 141 146 151 156",
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
            )
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for Gyrostat {
        const LAGRANGIAN: &'static str = "0.5·(ω₃·(ω₃·inertia[(2,2)] + ω₁·inertia[(0,2)] + ω₂·inertia[(1,2)]) + ω₁·(ω₃·inertia[(0,2)] + ω₁·inertia[(0,0)] + ω₂·inertia[(0,1)]) + ω₂·(ω₃·inertia[(1,2)] + ω₁·inertia[(0,1)] + ω₂·inertia[(1,1)])) + ω₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + ω₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + ω₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]) - mass·g·(γ₃·com[2] + γ₁·com[0] + γ₂·com[1])";
        const AMENDED_POTENTIAL: &'static str = "(γ₃·com[2]·mass·g + γ₁·com[0]·mass·g + γ₂·com[1]·mass·g) + 0.5·(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)])))^2 / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
        const PSI_DOT_AT_REST: &'static str = "(p_ψ - (γ₃·(rotor[2] + γ₃·coupling[(2,2)] + γ₁·coupling[(2,0)] + γ₂·coupling[(2,1)]) + γ₁·(rotor[0] + γ₃·coupling[(0,2)] + γ₁·coupling[(0,0)] + γ₂·coupling[(0,1)]) + γ₂·(rotor[1] + γ₃·coupling[(1,2)] + γ₁·coupling[(1,0)] + γ₂·coupling[(1,1)]))) / (γ₃·(γ₃·inertia[(2,2)] + γ₁·inertia[(0,2)] + γ₂·inertia[(1,2)]) + γ₁·(γ₃·inertia[(0,2)] + γ₁·inertia[(0,0)] + γ₂·inertia[(0,1)]) + γ₂·(γ₃·inertia[(1,2)] + γ₁·inertia[(0,1)] + γ₂·inertia[(1,1)]))";
    }
};
